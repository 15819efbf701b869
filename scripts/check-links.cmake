# Reads what the object files of src/ and bench/ use from each other against the table of
# src/modules.cmake: an #include is not the only way up, a function declared by hand is another,
# and the link would then point upward. Run after `prt` links (the top CMakeLists.txt).
#   cmake -D ROOT=<project folder> -D BUILD=<build folder> -D OBJECTS=<file: an object per line>
#         [-D NM=<nm>] [-D STAMP=<file touched when it passes>] -P scripts/check-links.cmake
# Each object is of the folder of its source: BUILD/[DIR/]CMakeFiles/TARGET.dir/PATH.o is DIR/PATH,
# the same under Ninja and Makefiles (a source of src/F is of F, of bench/ of bench; any other, a
# test's, is not read). An object of folder F that uses (nm: U) a symbol that only objects of
# folders F may not depend on define fails the check, named with both files:
#   link: src/app/commands.cpp uses prt::RunBench(...) defined in bench/cmd_bench.cpp; app may not depend on bench (src/modules.cmake)
# A symbol defined in F itself or in one of its dependencies passes (an inline function or a
# template has a weak copy in every object that uses it), and one that no object of ours defines
# (the standard library's, a third party's, a sanitizer's) is not ours to judge.
cmake_minimum_required(VERSION 3.20)
if(NOT ROOT OR NOT BUILD OR NOT OBJECTS)
  message(FATAL_ERROR "check-links: -D ROOT=<project folder> -D BUILD=<build folder> -D OBJECTS=<file> are required")
endif()
if(NOT NM)
  set(NM nm)
endif()
include("${CMAKE_CURRENT_LIST_DIR}/modules-table.cmake")
set(problems "")  # the table's own problems are the include check's to name

# The objects, each with its source (shown) and folder.
file(STRINGS "${OBJECTS}" listed)
set(objects "")
set(index 0)
foreach(object IN LISTS listed)
  if(object STREQUAL "")
    continue()
  endif()
  file(RELATIVE_PATH relative "${BUILD}" "${object}")
  string(REPLACE "/./" "/" relative "${relative}")  # Ninja writes CMakeFiles/T.dir/./x.cpp.o
  if(NOT relative MATCHES "^(.*/)?CMakeFiles/[^/]+\\.dir/(.+)\\.o(bj)?$")
    string(APPEND problems "link: ${object}: not an object of a CMake target under ${BUILD}\n")
    continue()
  endif()
  set(source "${CMAKE_MATCH_1}${CMAKE_MATCH_2}")
  if(source MATCHES "^src/([^/]+)/")
    set(module "${CMAKE_MATCH_1}")
  elseif(source MATCHES "^bench/")
    set(module bench)
  else()
    continue()
  endif()
  if(NOT module IN_LIST known)
    string(APPEND problems "link: ${source}: of a folder that src/modules.cmake does not list\n")
    continue()
  endif()
  if(NOT EXISTS "${object}")
    string(APPEND problems "link: ${object} (${source}) is missing: build it first\n")
    continue()
  endif()
  set(object_${index} "${object}")
  set(source_${index} "${source}")
  set(module_${index} "${module}")
  list(APPEND objects ${index})
  math(EXPR index "${index} + 1")
endforeach()
if(problems)
  message(NOTICE "check-links:\n${problems}")
  message(FATAL_ERROR "check-links: the objects could not be read (above)")
endif()

# One nm for all: the global symbols of each object, unsorted (-p). Mangled names are the keys
# (letters, digits, _ . $ only); the message demangles (nm -C) the few it names.
set(paths "")
foreach(i IN LISTS objects)
  list(APPEND paths "${object_${i}}")
endforeach()
execute_process(COMMAND "${NM}" -g -p ${paths} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "check-links: ${NM} failed (${status}): ${err}")
endif()
# nm names each object before its symbols ("\nPATH:\n") when it reads several, in their order.
string(REPLACE "\n" ";" lines "${out}")
list(LENGTH objects count)
set(at -1)
if(count EQUAL 1)  # nm names no file when it reads only one
  set(at 0)
endif()
foreach(line IN LISTS lines)
  if(line MATCHES "^ +U ([^ ]+)$")
    list(APPEND uses_${at} "${CMAKE_MATCH_1}")
  elseif(line MATCHES "^[0-9a-f]+ [TDBRWVuiGSC] ([^ ]+)$")
    set(symbol "${CMAKE_MATCH_1}")
    if(NOT DEFINED "in_${symbol}")
      set("in_${symbol}" "${module_${at}}")
      set("by_${symbol}" "${at}")
    elseif(NOT module_${at} IN_LIST "in_${symbol}")
      list(APPEND "in_${symbol}" "${module_${at}}")
    endif()
  elseif(line MATCHES "^(.+):$")
    math(EXPR at "${at} + 1")
    if(at GREATER_EQUAL count OR NOT CMAKE_MATCH_1 STREQUAL object_${at})
      message(FATAL_ERROR "check-links: ${NM} named '${CMAKE_MATCH_1}' where ${object_${at}} was due")
    endif()
  endif()
endforeach()

# Each use of a symbol another folder defines, against the table.
set(wrong "")  # object indices with a wrong use, for the names below
foreach(i IN LISTS objects)
  set(module "${module_${i}}")
  foreach(symbol IN LISTS uses_${i})
    if(NOT DEFINED "in_${symbol}" OR module IN_LIST "in_${symbol}")
      continue()
    endif()
    set(allowed FALSE)
    foreach(definer IN LISTS "in_${symbol}")
      if(definer IN_LIST deps_${module})
        set(allowed TRUE)
        break()
      endif()
    endforeach()
    if(NOT allowed)
      list(APPEND wrong_${i} "${symbol}")
      list(APPEND wrong ${i})
    endif()
  endforeach()
endforeach()

if(wrong)
  list(REMOVE_DUPLICATES wrong)
  foreach(i IN LISTS wrong)
    # The readable names: nm -C lists the same symbols in the same order (-p); the n-th use of
    # the mangled listing is the n-th line of the readable one.
    execute_process(COMMAND "${NM}" -p --undefined-only "${object_${i}}" OUTPUT_VARIABLE mangled)
    execute_process(COMMAND "${NM}" -p --undefined-only -C "${object_${i}}" OUTPUT_VARIABLE readable)
    string(REGEX MATCHALL "U [^\n]+" mangled "${mangled}")
    foreach(symbol IN LISTS wrong_${i})
      list(FIND mangled "U ${symbol}" line)
      set(name "${symbol}")
      set(rest "${readable}")
      while(line GREATER 0)
        string(FIND "${rest}" "\n" end)
        math(EXPR end "${end} + 1")
        string(SUBSTRING "${rest}" ${end} -1 rest)
        math(EXPR line "${line} - 1")
      endwhile()
      if(line EQUAL 0 AND rest MATCHES "^ *U ([^\n]+)")
        set(name "${CMAKE_MATCH_1}")
        # std::string and std::vector<std::string> as written in the source.
        string(REPLACE "std::__cxx11::basic_string<char, std::char_traits<char>, std::allocator<char> >"
               "std::string" name "${name}")
        string(REGEX REPLACE ", std::allocator<[^<>]*> ?>" ">" name "${name}")
      endif()
      list(GET "in_${symbol}" 0 folder)
      string(APPEND problems "link: ${source_${i}} uses ${name} defined in ${source_${by_${symbol}}}; "
             "${module_${i}} may not depend on ${folder} (src/modules.cmake)\n")
    endforeach()
  endforeach()
  # One line each (a message of FATAL_ERROR would wrap them), then the failure.
  message(NOTICE "check-links: objects that use what their folder may not include:\n${problems}")
  message(FATAL_ERROR "check-links: the link does not point one way (above)")
endif()
if(STAMP)
  file(TOUCH "${STAMP}")
endif()
