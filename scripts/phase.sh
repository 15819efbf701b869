# Sourced by quickstart.sh, sanitize.sh and .ci/run: each step of a run timed as a phase.
#   phase NAME COMMAND...   runs COMMAND; when PRT_PHASE_LOG names a file, appends
#                           "NAME<TAB>SECONDS<TAB>ok|failed" to it. Returns COMMAND's status.
#   phase_table FILE        prints the phases of FILE as a table, with their total.
phase() {
  local name=$1 start status=0
  shift
  start=$(date +%s)
  "$@" || status=$?
  if [ -n "${PRT_PHASE_LOG:-}" ]; then
    printf '%s\t%s\t%s\n' "$name" "$(($(date +%s) - start))" "$([ $status -eq 0 ] && echo ok || echo failed)" \
      >>"$PRT_PHASE_LOG"
  fi
  return $status
}

phase_table() {
  [ -s "$1" ] || return 0
  awk -F '\t' '
    BEGIN { printf "\n%-44s %8s\n", "phase", "seconds" }
    { printf "%-44s %8d%s\n", $1, $2, ($3 == "ok" ? "" : "  (" $3 ")"); total += $2 }
    END { printf "%-44s %8d\n", "total", total }
  ' "$1"
}
