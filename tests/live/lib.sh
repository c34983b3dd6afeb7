# Helpers the live tests share (sourced after setting `ev`, the event log of `passlab run
# --events`; `wait_s` seconds, default 20, bounds every wait).

# count PATTERN: lines of the event log that match (0 before the log exists).
count() { c=$(grep -c "$1" "$ev" 2>/dev/null) || c=0; echo "${c:-0}"; }

# wait_for PATTERN COUNT: until the log has COUNT matching lines; on timeout prints the log
# (without the per-frame events) and ends the test.
wait_for() {
  i=0 limit=$((${wait_s:-20} * 10))
  while [ "$(count "$1")" -lt "$2" ]; do
    i=$((i + 1)); [ $i -lt $limit ] || { echo "timed out waiting for $2 x $1" >&2; grep -v frame-presented "$ev" >&2; exit 1; }
    sleep 0.1
  done
}
