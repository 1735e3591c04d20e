#!/usr/bin/env bash
# Runs a command and prints, every 0.5 s, the seconds since its start and the
# resident set (MB) of the process named PROCESS it starts (how the painter's
# memory figures in docs/benchmarks.md were taken); the largest last.
#   bash tools/rss_trace.sh PROCESS -- COMMAND ...
set -u
[ $# -ge 3 ] && [ "$2" = "--" ] || { echo "usage: bash tools/rss_trace.sh PROCESS -- COMMAND ..." >&2; exit 2; }
name=$1
shift 2
"$@" >/dev/null 2>&1 &
child=$!
start=$(date +%s.%N)
peak=0
while kill -0 "$child" 2>/dev/null; do
  pid=$(pgrep -x "$name" | head -n 1)
  if [ -n "$pid" ]; then
    kb=$(awk '/VmRSS/{print $2}' "/proc/$pid/status" 2>/dev/null)
    if [ -n "$kb" ]; then
      printf '%.1f s %d MB\n' "$(awk -v now="$(date +%s.%N)" -v start="$start" 'BEGIN { print now - start }')" $((kb / 1024))
      [ "$kb" -gt "$peak" ] && peak=$kb
    fi
  fi
  sleep 0.5
done
wait "$child"
status=$?
echo "peak $((peak / 1024)) MB (exit $status)"
exit $status
