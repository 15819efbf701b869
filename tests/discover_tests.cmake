# Registers every doctest test case of prt_tests as a CTest test of its own, labelled with its
# TEST_SUITE (ctest -L geometry), from ONE listing of the program:
#   prt_tests --list-test-cases --reporters=xml
# names each case with its suite. doctest-dev's own doctest_discover_tests asks for each case's
# suite with a process of its own (465 starts of the test program after every link: 77 s of each
# sanitized build, measured on 2 vCPUs) and cuts a name at each ';' into tests whose filters
# select nothing (8 cases never ran under CTest that way), which is why prt has this script.
#
# Run after each link of prt_tests (a POST_BUILD step, tests/CMakeLists.txt) with
#   -D TEST_EXECUTABLE=... -D CTEST_FILE=... -D TEST_WORKING_DIR=... -D TEST_TIMEOUT=...
#   -D SKIP_RETURN_CODE=...
# It writes CTEST_FILE, which CTest includes (TEST_INCLUDE_FILES).

execute_process(
  COMMAND "${TEST_EXECUTABLE}" --list-test-cases --reporters=xml --no-intro=true
  OUTPUT_VARIABLE listing
  RESULT_VARIABLE result
  WORKING_DIRECTORY "${TEST_WORKING_DIR}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "listing the test cases of ${TEST_EXECUTABLE} failed (${result}):\n${listing}")
endif()

# CMake lists split at ';' and keep '[' ']' together: hide the three before splitting.
string(REPLACE ";" "<semicolon>" listing "${listing}")
string(REPLACE "[" "<open>" listing "${listing}")
string(REPLACE "]" "<close>" listing "${listing}")
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
  # doctest splits a --test-case filter at commas: the run escapes them.
  string(REPLACE "," "\\," filter "${name}")
  string(APPEND script
    "add_test([==[${name}]==] [==[${TEST_EXECUTABLE}]==] [==[--test-case=${filter}]==] --no-intro=true)\n"
    "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY [==[${TEST_WORKING_DIR}]==] "
    "LABELS [==[${suite}]==] SKIP_RETURN_CODE ${SKIP_RETURN_CODE} TIMEOUT ${TEST_TIMEOUT})\n")
  math(EXPR count "${count} + 1")
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} listed no test cases:\n${listing}")
endif()
file(WRITE "${CTEST_FILE}" "${script}")
