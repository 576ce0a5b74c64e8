"""granrepro.report: the static HTML report of a results folder (`granrepro report`).
`python3 -m granrepro.report --help`; make_report() is the function behind it."""
from .build import BadInput, make_report  # noqa: F401
