# The e2e tier's smoke set under a sanitizer (tests/smoke.txt, tests/README.md "Tiers"). A
# sanitized build folder compiles no e2e test: those tests only start `prt` and read what it
# writes, so the e2e program of the Release build (PRT_SMOKE_DRIVER) runs them against this
# folder's sanitized `prt` (PRT_BINARY), with scratch folders of this folder's own (PRT_TEST_TMP).
# CTest registers them when it starts, from one listing of that program (discover_tests.cmake
# with the smoke list), so a Release build made after this folder's is the one run. Included by
# tests/CMakeLists.txt, which defines prt_include_file.
if(PRT_SANITIZE OR PRT_TSAN)
  set(PRT_SMOKE_DRIVER "${PROJECT_SOURCE_DIR}/build/prt_e2e_tests" CACHE FILEPATH
      "The e2e test program of an unsanitized build, which runs the smoke set against this build's prt")
  if(PRT_SANITIZE)
    set(prt_smoke_pass asan)
  else()
    set(prt_smoke_pass tsan)
  endif()
  set(prt_smoke_env "PRT_BINARY=$<TARGET_FILE:prt>;PRT_TEST_TMP=${PROJECT_BINARY_DIR}/test-tmp")
  set(prt_smoke_cases "${PROJECT_BINARY_DIR}/prt_smoke_cases.cmake")
  file(GENERATE OUTPUT "${PROJECT_BINARY_DIR}/prt_smoke_include.cmake" CONTENT
"if(EXISTS [==[${PRT_SMOKE_DRIVER}]==])
  set(TEST_EXECUTABLE [==[${PRT_SMOKE_DRIVER}]==])
  set(TIER e2e)
  set(TEST_WORKING_DIR [==[${PROJECT_BINARY_DIR}]==])
  set(CTEST_FILE [==[${prt_smoke_cases}]==])
  set(TEST_TIMEOUT ${prt_test_timeout})
  set(SKIP_RETURN_CODE 77)
  set(SMOKE_LIST [==[${CMAKE_CURRENT_SOURCE_DIR}/smoke.txt]==])
  set(SMOKE_PASS ${prt_smoke_pass})
  set(SMOKE_ENVIRONMENT [==[${prt_smoke_env}]==])
  include([==[${CMAKE_CURRENT_SOURCE_DIR}/discover_tests.cmake]==])
  include([==[${prt_smoke_cases}]==])
else()
  add_test(prt_smoke_NO_DRIVER [==[${PRT_SMOKE_DRIVER}]==])
endif()
")
  file(APPEND "${prt_include_file}" "include(\"${PROJECT_BINARY_DIR}/prt_smoke_include.cmake\")\n")
endif()
