# Sourced by the study scripts: read a scalar from a run's summary.json and format it.
# First numeric value of a scalar in summary.json (scalars come before units there).
get() { awk -v k="\"$1\":" '$1 == k { v = $2; sub(/,$/, "", v); print v; exit }' "$2"; }
# printf-format a value, "-" when it is missing or null.
fmt() { awk -v v="$1" -v f="$2" 'BEGIN { if (v == "" || v == "null") print "-"; else printf f, v }'; }
