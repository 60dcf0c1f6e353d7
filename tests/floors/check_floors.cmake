# The floor plan (docs/architecture.md), checked on the includes of the tree: cmake -DSOURCE_DIR=... -P
# check_floors.cmake exits non-zero naming every file that breaks a rule, and the include that does.
#
#   1. A library room includes only rooms on its own floor or below: core, scene, setup, engine, log,
#      replay, run, analysis (and the public headers, ede/).
#   2. replay/ reads logs and never runs the engine: it includes nothing from engine/ or setup/ (the re-run
#      that verify needs is in run/). log/ is the format and owns its arithmetic (log/rules/): it includes
#      nothing from engine/ either, though the engine is a floor below (the sink it implements is core's).
#   3. study/ and the benchmarks (tools/ede_bench, tools/ede_bench_elastic) reach the library's inside only
#      through the internal tier, ede/internal/: no include names a folder of libede/src.
#   4. Every other tool and the Python module use the public headers alone: no libede/src folder, no
#      ede/internal/, and no LogReader (the library's internal reader; they read logs through ede::Log).
#   5. No public header (ede/*.hpp) names LogReader.
# Rejected: a compile-time check through include paths alone (the internal tier forwards into libede/src,
# so its users' include path must hold it; what they may name is a rule about the text).
cmake_minimum_required(VERSION 3.20)
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "pass -DSOURCE_DIR=<the ede source tree>")
endif()

set(rooms core scene setup engine log replay run analysis)
set(room_regex "^(core|scene|setup|engine|log|replay|run|analysis)/")
set(failures "")

# The quoted includes of a file, one per list entry (the path inside the quotes).
function(quoted_includes file out)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]+\"")
  set(paths "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*$" "\\1" path "${line}")
    list(APPEND paths "${path}")
  endforeach()
  set(${out} "${paths}" PARENT_SCOPE)
endfunction()

macro(fail file what)
  file(RELATIVE_PATH rel ${SOURCE_DIR} ${file})
  string(APPEND failures "  ${rel}: ${what}\n")
endmacro()

# Rules 1 and 2.
foreach(room IN LISTS rooms)
  list(FIND rooms ${room} floor)
  file(GLOB_RECURSE files ${SOURCE_DIR}/libede/src/${room}/*.hpp ${SOURCE_DIR}/libede/src/${room}/*.cpp)
  foreach(file IN LISTS files)
    quoted_includes(${file} paths)
    foreach(path IN LISTS paths)
      if(NOT path MATCHES "${room_regex}")
        continue()
      endif()
      string(REGEX REPLACE "/.*$" "" target "${path}")
      list(FIND rooms ${target} target_floor)
      if(target_floor GREATER floor)
        fail(${file} "includes \"${path}\": ${target}/ is a floor above ${room}/")
      endif()
      if(room STREQUAL "replay" AND target MATCHES "^(engine|setup)$")
        fail(${file} "includes \"${path}\": replay/ never runs the engine (a re-run belongs in run/)")
      endif()
      if(room STREQUAL "log" AND target STREQUAL "engine")
        fail(${file} "includes \"${path}\": log/ includes nothing of the engine (the format's arithmetic is log/rules/)")
      endif()
    endforeach()
  endforeach()
endforeach()

# Rule 3.
file(GLOB_RECURSE tier_users ${SOURCE_DIR}/study/*.hpp ${SOURCE_DIR}/study/*.cpp
     ${SOURCE_DIR}/tools/ede_bench/*.hpp ${SOURCE_DIR}/tools/ede_bench/*.cpp
     ${SOURCE_DIR}/tools/ede_bench_elastic/*.cpp)
foreach(file IN LISTS tier_users)
  quoted_includes(${file} paths)
  foreach(path IN LISTS paths)
    if(path MATCHES "${room_regex}")
      fail(${file} "includes \"${path}\" from libede/src: use the internal tier (ede/internal/)")
    endif()
  endforeach()
endforeach()

# Rule 4.
file(GLOB_RECURSE public_users ${SOURCE_DIR}/tools/*.hpp ${SOURCE_DIR}/tools/*.cpp
     ${SOURCE_DIR}/python/src/*.hpp ${SOURCE_DIR}/python/src/*.cpp)
foreach(file IN LISTS public_users)
  if(file MATCHES "/tools/ede_bench(_elastic)?/")
    continue()
  endif()
  quoted_includes(${file} paths)
  foreach(path IN LISTS paths)
    if(path MATCHES "${room_regex}" OR path MATCHES "^ede/internal/")
      fail(${file} "includes \"${path}\": a tool or binding uses the public headers alone")
    endif()
  endforeach()
  file(STRINGS ${file} readers REGEX "LogReader")
  if(readers)
    fail(${file} "names LogReader: read logs through ede::Log (ede/log.hpp)")
  endif()
endforeach()

# Rule 5.
file(GLOB public_headers ${SOURCE_DIR}/libede/include/ede/*.hpp)
foreach(file IN LISTS public_headers)
  file(STRINGS ${file} readers REGEX "LogReader")
  if(readers)
    fail(${file} "names LogReader, an internal type")
  endif()
endforeach()

if(failures)
  message(FATAL_ERROR "The floor plan is broken (docs/architecture.md, \"The rooms\"):\n${failures}")
endif()
message(STATUS "floor plan: every include keeps to its floor")
