# Sourced by quickstart.sh and sanitize.sh: a build folder configured the same way by both.
#   configure FOLDER CMAKE_OPTION...   runs `cmake -S . -B FOLDER CMAKE_OPTION...`, quietly, with
#                                      Ninja when the folder is new and ninja is installed: Ninja
#                                      logs each compile's time, which scripts/slowest-files.sh
#                                      prints. A folder configured before keeps its generator.
#                                      Returns cmake's status.
configure() {
  local folder=$1 generator=()
  shift
  [ -f "$folder/CMakeCache.txt" ] || ! command -v ninja >/dev/null || generator=(-G Ninja)
  cmake -S . -B "$folder" "${generator[@]}" "$@" >/dev/null
}
