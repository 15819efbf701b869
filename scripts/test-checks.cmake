# The checks of the build catch what they should: scripts/check-includes.cmake (unit circles) and
# scripts/check-links.cmake (a function of a higher folder declared by hand), each run on small
# made-up trees, one with the fault it must name and one without, which must pass.
#   cmake -D ROOT=<project folder> -D WORK=<scratch folder> -D CXX=<C++ compiler> [-D NM=<nm>]
#         -P scripts/test-checks.cmake
# Registered as a test of the unit tier (the top CMakeLists.txt); about a second.
cmake_minimum_required(VERSION 3.20)
if(NOT ROOT OR NOT WORK OR NOT CXX)
  message(FATAL_ERROR "test-checks: -D ROOT=<project folder> -D WORK=<scratch folder> -D CXX=<compiler> are required")
endif()
if(NOT NM)
  set(NM nm)
endif()
file(REMOVE_RECURSE "${WORK}")
set(failures "")

# A made-up project under WORK/NAME with TABLE as its src/modules.cmake; put() writes its files
# (one argument each, as C++ has semicolons).
function(tree name table)
  file(WRITE "${WORK}/${name}/src/modules.cmake" "set(PRT_MODULES\n${table})\n")
  file(MAKE_DIRECTORY "${WORK}/${name}/bench")
endfunction()
function(put name path text)
  file(WRITE "${WORK}/${name}/${path}" "${text}\n")
endfunction()

# Runs a check (includes or links) on WORK/NAME, which must pass or fail; said() then counts a
# text in what it printed.
function(check name what verdict)
  set(root "${WORK}/${name}")
  if(what STREQUAL "includes")
    set(command "${CMAKE_COMMAND}" -D "ROOT=${root}" -P "${ROOT}/scripts/check-includes.cmake")
  else()
    set(command "${CMAKE_COMMAND}" -D "ROOT=${root}" -D "BUILD=${root}/build" -D "OBJECTS=${root}/objects.txt"
                -D "NM=${NM}" -P "${ROOT}/scripts/check-links.cmake")
  endif()
  execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(said "${out}${err}" PARENT_SCOPE)
  set(case "${name} (${what})" PARENT_SCOPE)
  if(verdict STREQUAL "passes" AND NOT status EQUAL 0)
    set(failures "${failures}${name} (${what}): should pass, failed; it said:\n${out}${err}\n" PARENT_SCOPE)
  elseif(verdict STREQUAL "fails" AND status EQUAL 0)
    set(failures "${failures}${name} (${what}): should fail, passed; it said:\n${out}${err}\n" PARENT_SCOPE)
  else()
    message(STATUS "ok: ${name} (${what}) ${verdict}")
  endif()
endfunction()
function(said times text)
  string(REPLACE "${text}" "" without "${said}")
  string(LENGTH "${said}" all)
  string(LENGTH "${without}" rest)
  string(LENGTH "${text}" one)
  math(EXPR found "(${all} - ${rest}) / ${one}")
  if(NOT found EQUAL times)
    set(failures "${failures}${case}: '${text}' said ${found} times, not ${times}; it said:\n${said}\n" PARENT_SCOPE)
  endif()
endfunction()

# ---- unit circles: three folders low <- mid <- top, units in each ----
set(table "  \"low:\"\n  \"mid: low\"\n  \"top: low mid\"\n  \"bench: top\"\n")
function(units name)  # units that include each other one way only
  tree(${name} "${table}")
  put(${name} src/low/low.h "#pragma once")
  put(${name} src/mid/a.h "#pragma once\n#include \"mid/b.h\"\n#include \"low/low.h\"")
  put(${name} src/mid/a.cpp "#include \"mid/a.h\"\n#include \"mid/c.h\"")
  put(${name} src/mid/b.h "#pragma once\n#include \"mid/c.h\"")
  put(${name} src/mid/b.cpp "#include \"mid/b.h\"\n#include \"mid/c.h\"")
  put(${name} src/mid/c.h "#pragma once")
  put(${name} src/top/x.h "#pragma once\n#include \"mid/a.h\"")
  put(${name} src/top/x.cpp "#include \"top/x.h\"\n#include \"top/y.h\"\n#include \"low/low.h\"")
  put(${name} src/top/y.h "#pragma once")
  put(${name} bench/run.cpp "#include \"top/x.h\"\n#include \"bench/run.h\"")
  put(${name} bench/run.h "#pragma once")
endfunction()
units(units-clean)
check(units-clean includes passes)

# b.cpp includes a.h, a.h includes b.h: a -> b -> a, named once (from a, its first unit).
units(units-two)
put(units-two src/mid/b.cpp "#include \"mid/b.h\"\n\n#include \"mid/a.h\"")
check(units-two includes fails)
said(1 "src/mid: unit circle a -> b -> a (src/mid/a.h:2, src/mid/b.cpp:3)")
said(1 "unit circle")

# x.cpp -> y.h, y.h -> z.h, z.cpp -> x.h: three units, in order; bench's are read the same way,
# an indented include too.
units(units-three)
put(units-three src/top/y.h "#pragma once\n#include \"top/z.h\"")
put(units-three src/top/z.h "#pragma once")
put(units-three src/top/z.cpp "#include \"top/z.h\"\n#include \"top/x.h\"")
put(units-three bench/run.h "#pragma once\n  #  include \"bench/more.h\"")
put(units-three bench/more.h "#pragma once\n#include \"bench/run.h\"")
check(units-three includes fails)
said(1 "src/top: unit circle x -> y -> z -> x (src/top/x.cpp:2, src/top/y.h:2, src/top/z.cpp:2)")
said(1 "bench: unit circle more -> run -> more (bench/more.h:2, bench/run.h:2)")
said(2 "unit circle")

# Two circles through a: each named once, the shortest through each unit.
units(units-both)
put(units-both src/mid/c.h "#pragma once\n#include \"mid/a.h\"")
put(units-both src/mid/b.cpp "#include \"mid/b.h\"\n#include \"mid/a.h\"")
check(units-both includes fails)
said(1 "src/mid: unit circle a -> b -> a")
said(1 "src/mid: unit circle a -> c -> a")
said(2 "unit circle")

# ---- links: low <- top, and bench on top; the objects laid out as CMake lays them out ----
set(table "  \"low:\"\n  \"top: low\"\n  \"bench: top\"\n")
function(objects name)  # compiles WORK/NAME's sources into WORK/NAME/build, listed in objects.txt
  set(root "${WORK}/${name}")
  file(GLOB_RECURSE sources RELATIVE "${root}" "${root}/src/*.cpp" "${root}/bench/*.cpp")
  list(SORT sources)
  set(listed "")
  foreach(source IN LISTS sources)
    if(source MATCHES "^bench/(.*)")  # a target of bench/CMakeLists.txt, as Makefiles write it
      set(object "${root}/build/bench/CMakeFiles/prtbench.dir/${CMAKE_MATCH_1}.o")
    else()  # a target of the top folder, as Ninja writes it
      set(object "${root}/build/CMakeFiles/prtcore.dir/./${source}.o")
    endif()
    string(APPEND listed "${object}\n")
    if(EXISTS "${object}")  # copied with the tree it was made from
      continue()
    endif()
    get_filename_component(folder "${object}" DIRECTORY)
    file(MAKE_DIRECTORY "${folder}")
    execute_process(COMMAND "${CXX}" -std=c++17 -O1 -I "${root}/src" -c "${root}/${source}" -o "${object}"
                    RESULT_VARIABLE status ERROR_VARIABLE err)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "test-checks: ${CXX} could not compile ${source}: ${err}")
    endif()
  endforeach()
  file(WRITE "${root}/objects.txt" "${listed}")
endfunction()
function(links name)
  # low's function and top's use of it, declared by hand (allowed); a template with a weak copy
  # in the objects of both folders; what the standard library defines (not ours to judge); a use
  # inside one folder (top's own function in another file of top)
  tree(${name} "${table}")
  put(${name} src/low/low.h "#pragma once\n#include <string>\ntemplate <typename T> int Size(const T& t) { return static_cast<int>(t.size()); }")
  put(${name} src/low/low.cpp "#include \"low/low.h\"\nnamespace prt { int Low(const std::string& s) { return Size(s); } }")
  put(${name} src/top/top.cpp "#include <string>\n#include \"low/low.h\"\nnamespace prt {\nint Low(const std::string& s);\nint Top() { return Low(\"a\") + Size(std::string(\"b\")); }\n}")
  put(${name} src/top/more.cpp "namespace prt {\nint Top();\nint More() { return Top(); }\n}")
  put(${name} bench/bench.cpp "namespace prt {\nint Top();\nint Bench() { return Top(); }\n}")
endfunction()
links(links-clean)
objects(links-clean)
check(links-clean links passes)

# low calls top's function, declared by hand; top calls bench's (the clean tree and its objects,
# and three files more).
file(COPY "${WORK}/links-clean/" DESTINATION "${WORK}/links-up")
put(links-up src/low/up.cpp "namespace prt {\nint Top();\nint Up() { return Top(); }\n}")
put(links-up src/top/run.cpp "#include <string>\n#include <vector>\nnamespace prt {\nint RunBench(const std::vector<std::string>& tokens);\nint Run() { return RunBench({}); }\n}")
put(links-up bench/cmd_bench.cpp "#include <string>\n#include <vector>\nnamespace prt {\nint RunBench(const std::vector<std::string>& tokens) { return static_cast<int>(tokens.size()); }\n}")
objects(links-up)
check(links-up links fails)
said(1 "link: src/low/up.cpp uses prt::Top() defined in src/top/top.cpp; low may not depend on top (src/modules.cmake)")
said(1 "link: src/top/run.cpp uses prt::RunBench(std::vector<std::string> const&) defined in bench/cmd_bench.cpp; top may not depend on bench (src/modules.cmake)")
said(2 "link: ")

if(failures)
  message(NOTICE "${failures}")
  message(FATAL_ERROR "test-checks: a check did not catch what it should (above)")
endif()
