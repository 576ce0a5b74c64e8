"""Reading a results folder, which is untrusted input (docs/schema.md, "Trust model"): the Python
side of src/core/untrusted_file.hpp, with the same caps. A file is read only if it is a regular
file reached without a symlink in its last component (O_NOFOLLOW | O_NONBLOCK, so a FIFO never
blocks) and no larger than its cap; JSON is refused past a nesting depth before json.loads, whose
recursion would otherwise end in RecursionError. Failures raise ResultsError: one line naming the
file."""
from __future__ import annotations

import errno
import json
import os
import re
import stat

# The caps of src/core/untrusted_file.hpp (kMax*): far above what any run writes.
MAX_SUMMARY_BYTES = 64 << 20     # summary.json (and the claims file `granrepro report` hands over)
MAX_POINT_FILE_BYTES = 256 << 20  # /points/records
MAX_TEXT_FILE_BYTES = 8 << 20    # TOML, .gp scripts, logs
MAX_IMAGE_BYTES = 64 << 20       # a figure (PNG, PDF)
MAX_JSON_DEPTH = 64              # every file granrepro writes nests at most 6 deep

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
PDF_MAGIC = b"%PDF-"


class ResultsError(ValueError):
    """A results folder (data.h5, summary.json, a figure) is damaged, edited or not granrepro's:
    the message is one line naming the file and the field. `granrepro report` exits 2 on it."""


def _kind(mode: int) -> str:
    if stat.S_ISLNK(mode):
        return "a symbolic link"
    if stat.S_ISDIR(mode):
        return "a directory"
    if stat.S_ISFIFO(mode):
        return "a FIFO"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def _reason(e: OSError) -> str:
    text = e.strerror or str(e)
    return text[:1].lower() + text[1:] if text[1:2].islower() else text


def _mib(n: int) -> str:
    return f"{n >> 20} MiB"


def open_regular(path: str, role: str) -> int:
    """A read-only descriptor of `path` if it is a regular file and not a symlink."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError as e:
        if e.errno == errno.ELOOP and os.path.islink(path):
            raise ResultsError(f"{path}: {role} is a symbolic link; a results folder is read without following links") from None
        raise ResultsError(f"{path}: {role} cannot be read ({_reason(e)})") from None
    try:
        mode = os.fstat(fd).st_mode
    except OSError as e:
        os.close(fd)
        raise ResultsError(f"{path}: {role} cannot be read ({_reason(e)})") from None
    if not stat.S_ISREG(mode):
        os.close(fd)
        raise ResultsError(f"{path}: {role} is {_kind(mode)}, not a regular file")
    return fd


def read_file(path: str, cap: int, role: str, head: int | None = None) -> bytes:
    """The content of `path` (a regular file, not a symlink) of at most `cap` bytes; with `head`,
    only its first `head` bytes (the size is still checked)."""
    fd = open_regular(path, role)
    try:
        if os.fstat(fd).st_size > cap:
            raise ResultsError(f"{path}: {role} is larger than its cap of {_mib(cap)} (docs/schema.md)")
        want = cap + 1 if head is None else head
        chunks, done = [], 0
        while done < want:  # the size may change while we read: never past the cap
            b = os.read(fd, min(want - done, 1 << 20))
            if not b:
                break
            chunks.append(b)
            done += len(b)
    except OSError as e:
        raise ResultsError(f"{path}: {role} cannot be read ({_reason(e)})") from None
    finally:
        os.close(fd)
    if done > cap:
        raise ResultsError(f"{path}: {role} is larger than its cap of {_mib(cap)} (docs/schema.md)")
    return b"".join(chunks)


def require_regular_file(path: str, role: str) -> None:
    """For files a library opens by name (h5py): refuses a symlink, FIFO, device or directory."""
    try:
        mode = os.lstat(path).st_mode
    except OSError as e:
        raise ResultsError(f"{path}: {role} cannot be read ({_reason(e)})") from None
    if stat.S_ISLNK(mode):
        raise ResultsError(f"{path}: {role} is a symbolic link; a results folder is read without following links")
    if not stat.S_ISREG(mode):
        raise ResultsError(f"{path}: {role} is {_kind(mode)}, not a regular file")


_STRING = re.compile(r'"[^"\\]*(?:\\.[^"\\]*)*"', re.S)
_NOT_BRACKET = re.compile(r"[^\[\]{}]+")


def json_depth(text: str) -> int:
    """The deepest nesting of [ and { outside strings (as json_depth in untrusted_file.cpp)."""
    import numpy as np

    brackets = _NOT_BRACKET.sub("", _STRING.sub("", text)).encode("ascii")
    if not brackets:
        return 0
    b = np.frombuffer(brackets, dtype=np.uint8)
    steps = np.where((b == ord("[")) | (b == ord("{")), 1, -1)
    return int(np.cumsum(steps).max())


def parse_json(data: bytes, file: str):
    """`data` (UTF-8 JSON text) parsed, refused naming `file` if it is not UTF-8, not JSON, or
    nests deeper than MAX_JSON_DEPTH."""
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise ResultsError(f"{file}: not UTF-8 text (byte {e.start}); granrepro writes UTF-8 JSON") from None
    if json_depth(text) > MAX_JSON_DEPTH:
        raise ResultsError(f"{file}: JSON nested deeper than {MAX_JSON_DEPTH} levels (not a granrepro file)")
    def not_json(name):  # NaN and Infinity: Python's json takes them, JSON (and nlohmann) does not
        raise ValueError(f"{name} is not JSON")
    try:
        return json.loads(text, parse_constant=not_json)
    except (ValueError, RecursionError) as e:
        raise ResultsError(f"{file}: not valid JSON (a damaged file?): {str(e).splitlines()[0][:120]}") from None


def read_json(path: str, cap: int, role: str):
    return parse_json(read_file(path, cap, role), path)


def printable(text: str) -> str:
    """`text` with control characters (a newline, a terminal escape) written as \\xNN, so that a
    message stays one line and a file cannot drive the terminal."""
    return re.sub(r"[\x00-\x1f\x7f-\x9f]", lambda m: f"\\x{ord(m.group()):02x}", text)
