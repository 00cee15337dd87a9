# Specification: an engine's build can use kiln both ways the README describes.
#  1. kiln installed (cmake --install): find_package(kiln) gives kiln::lut (header only),
#     kiln::runtime (with the EXR loader) and the kiln executable, whose --version answers.
#  2. kiln's runtime/ folder added with add_subdirectory: the same two targets.
#  3. the whole kiln project added with add_subdirectory: configures, with kiln::kiln too (not
#     built here: that is the whole baker; kiln's own build is that build).
# Each way builds tests/downstream, runs its in-memory sample, and samples luts/ggx-dfg.exr,
# which must print exactly what `kiln sample` prints.
# Run by CTest: cmake -DKILN_BUILD_DIR=... -DKILN_SOURCE_DIR=... -DKILN=... -P downstream.cmake
foreach(var KILN_BUILD_DIR KILN_SOURCE_DIR KILN)
  if(NOT ${var})
    message(FATAL_ERROR "downstream.cmake: ${var} is not set")
  endif()
endforeach()
string(RANDOM LENGTH 10 tag)
set(work "${KILN_BUILD_DIR}/downstream-${tag}")  # unique: two test runs may share a build
set(table "${KILN_SOURCE_DIR}/luts/ggx-dfg.exr")

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGV}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

run(${KILN} sample ${table} 0.5 0.3)
set(expected "${out}")

run(${CMAKE_COMMAND} --install ${KILN_BUILD_DIR} --prefix ${work}/prefix)
run(${work}/prefix/bin/kiln --version)
if(NOT out MATCHES "^kiln [0-9]+\\.[0-9]+\\.[0-9]+")
  message(FATAL_ERROR "installed kiln --version printed '${out}'")
endif()

run(${CMAKE_COMMAND} -S ${KILN_SOURCE_DIR}/tests/downstream -B ${work}/project
    -DCMAKE_BUILD_TYPE=Release -DKILN_PROJECT_DIR=${KILN_SOURCE_DIR})
message(STATUS "project: configured")

foreach(way package subdirectory)
  if(way STREQUAL "package")
    set(how -DCMAKE_PREFIX_PATH=${work}/prefix)
  else()
    set(how -DKILN_RUNTIME_DIR=${KILN_SOURCE_DIR}/runtime)
  endif()
  run(${CMAKE_COMMAND} -S ${KILN_SOURCE_DIR}/tests/downstream -B ${work}/${way}
      -DCMAKE_BUILD_TYPE=Release ${how})
  run(${CMAKE_COMMAND} --build ${work}/${way} -j 2)
  run(${work}/${way}/sample_in_memory)
  run(${work}/${way}/sample_file ${table} 0.5 0.3)
  if(NOT out STREQUAL expected)
    message(FATAL_ERROR "${way}: sample_file printed '${out}', kiln sample '${expected}'")
  endif()
  message(STATUS "${way}: ok")
endforeach()
file(REMOVE_RECURSE ${work})
