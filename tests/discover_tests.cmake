# Registers every doctest test case of a test program as a CTest test of its own, labelled with
# its TEST_SUITE and the program's tier (ctest -L geometry, ctest -L unit), from ONE listing of
# the program:
#   prt_unit_tests --list-test-cases --reporters=xml
# names each case with its suite. doctest-dev's own doctest_discover_tests asks for each case's
# suite with a process of its own (465 starts of the test program after every link: 77 s of each
# sanitized build, measured on 2 vCPUs) and cuts a name at each ';' into tests whose filters
# select nothing (8 cases never ran under CTest that way), which is why prt has this script.
#
# Run after each link of a test program (a POST_BUILD step, tests/CMakeLists.txt) with
#   -D TEST_EXECUTABLE=... -D TIER=... -D CTEST_FILE=... -D TEST_WORKING_DIR=...
#   -D TEST_TIMEOUT=... -D SKIP_RETURN_CODE=...
# It writes CTEST_FILE, which CTest includes (TEST_INCLUDE_FILES).
#
# For a sanitizer pass's smoke set (tests/smoke.cmake) it is included instead, with SMOKE_LIST
# (tests/smoke.txt), SMOKE_PASS (asan or tsan) and SMOKE_ENVIRONMENT (the variables that point the
# Release build's e2e program at the sanitized prt) set: then only the cases the list names for
# that pass are registered, each with those variables and the labels SUITE;e2e;smoke, and a name
# in the list that the program does not have is an error (the list follows the tests).

execute_process(
  COMMAND "${TEST_EXECUTABLE}" --list-test-cases --reporters=xml --no-intro=true
  OUTPUT_VARIABLE listing
  RESULT_VARIABLE result
  WORKING_DIRECTORY "${TEST_WORKING_DIR}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "listing the test cases of ${TEST_EXECUTABLE} failed (${result}):\n${listing}")
endif()

# CMake lists split at ';' and keep '[' ']' together: hide the three before splitting.
function(prt_hide out text)
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "[" "<open>" text "${text}")
  string(REPLACE "]" "<close>" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()
prt_hide(listing "${listing}")
string(REGEX MATCHALL "<TestCase name=\"[^\"]*\"( testsuite=\"[^\"]*\")?" cases "${listing}")

# The three characters back (a '<' in the XML is always &lt;, so these are ours), then the XML's
# escapes undone, &amp; last.
function(prt_unescape out text)
  foreach(pair "<semicolon>|;" "<open>|[" "<close>|]" "&quot;|\"" "&apos;|'" "&lt;|<" "&gt;|>" "&amp;|&")
    string(FIND "${pair}" "|" bar)
    string(SUBSTRING "${pair}" 0 ${bar} from)
    math(EXPR bar "${bar} + 1")
    string(SUBSTRING "${pair}" ${bar} -1 to)
    string(REPLACE "${from}" "${to}" text "${text}")
  endforeach()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# The smoke set: the names tests/smoke.txt gives this pass ("asan: NAME", "tsan: NAME"), with
# the three characters hidden as in the listing, so that names compare as lists.
set(smoke "")
if(DEFINED SMOKE_LIST)
  file(READ "${SMOKE_LIST}" smoke_text)
  prt_hide(smoke_text "${smoke_text}")
  string(REGEX MATCHALL "(^|\n)${SMOKE_PASS}: [^\n]+" smoke_lines "${smoke_text}")
  foreach(line IN LISTS smoke_lines)
    string(REGEX REPLACE "^\n?${SMOKE_PASS}: " "" line "${line}")
    list(APPEND smoke "${line}")
  endforeach()
  set(smoke_found "")
endif()

set(script "")
set(count 0)
foreach(entry IN LISTS cases)
  string(REGEX REPLACE "^<TestCase name=\"([^\"]*)\".*$" "\\1" name "${entry}")
  prt_unescape(name "${name}")
  # The label is the suite, and the sanitizer passes choose tests by label: a case outside every
  # TEST_SUITE would be left out of them unseen.
  if(NOT entry MATCHES " testsuite=\"([^\"]+)\"$")
    message(FATAL_ERROR "test case '${name}' is in no TEST_SUITE: put it in its module's suite")
  endif()
  prt_unescape(suite "${CMAKE_MATCH_1}")
  set(labels "${suite};${TIER}")
  set(environment "")
  if(DEFINED SMOKE_LIST)
    # Compared with the list's lines through the same hiding.
    prt_hide(hidden "${name}")
    list(FIND smoke "${hidden}" at)
    if(at EQUAL -1)
      continue()
    endif()
    list(APPEND smoke_found "${hidden}")
    set(labels "${suite};${TIER};smoke")
    set(environment " ENVIRONMENT [==[${SMOKE_ENVIRONMENT}]==]")
  endif()
  # doctest splits a --test-case filter at commas: the run escapes them.
  string(REPLACE "," "\\," filter "${name}")
  string(APPEND script
    "add_test([==[${name}]==] [==[${TEST_EXECUTABLE}]==] [==[--test-case=${filter}]==] --no-intro=true)\n"
    "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY [==[${TEST_WORKING_DIR}]==] "
    "LABELS [==[${labels}]==] SKIP_RETURN_CODE ${SKIP_RETURN_CODE} TIMEOUT ${TEST_TIMEOUT}${environment})\n")
  math(EXPR count "${count} + 1")
endforeach()
if(DEFINED SMOKE_LIST)
  foreach(wanted IN LISTS smoke)
    list(FIND smoke_found "${wanted}" at)
    if(at EQUAL -1)
      prt_unescape(wanted "${wanted}")
      message(FATAL_ERROR "${SMOKE_LIST} names '${wanted}' for ${SMOKE_PASS}, which ${TEST_EXECUTABLE} does not have")
    endif()
  endforeach()
  file(WRITE "${CTEST_FILE}" "${script}")
  return()
endif()
if(count EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} listed no test cases:\n${listing}")
endif()
file(WRITE "${CTEST_FILE}" "${script}")
