# Specification: an engine's build can use kiln both ways the README describes.
#  1. kiln installed (cmake --install): find_package(kiln) gives kiln::lut (header only),
#     kiln::runtime (with the EXR loader) and the kiln executable, whose --version answers.
#  2. kiln's runtime/ folder added with add_subdirectory: the same two targets (in a Debug
#     build, the package's in Release).
#  3. the whole kiln project added with add_subdirectory: configures, with kiln::kiln too (not
#     built here: that is the whole baker; kiln's own build is that build).
# The package also holds every shader snippet of runtime/shaders in include/kiln/shaders, and
# tests/downstream's package build reads KILN_SHADER_DIR (the same folder).
# Each way builds tests/downstream, runs its in-memory sample, and samples luts/ggx-dfg.exr,
# which must print exactly what `kiln sample` prints. The package way also bakes a table with
# kiln_bake() as a build step, samples it, and builds twice more: with nothing changed nothing
# runs; with the stamp removed kiln runs and says the table is up to date, which stays the same
# file (inode and mtime).
# Run by CTest: cmake -DKILN_BUILD_DIR=... -DKILN_SOURCE_DIR=... -DKILN=... -P downstream.cmake
# -DKILN_DOWNSTREAM_WAYS=package or =subdirectory,project checks those ways alone (CTest runs the
# two halves as tests of their own); unset: all three.
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...)
foreach(var KILN_BUILD_DIR KILN_SOURCE_DIR KILN)
  if(NOT ${var})
    message(FATAL_ERROR "downstream.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT DEFINED KILN_DOWNSTREAM_WAYS)
  set(KILN_DOWNSTREAM_WAYS package subdirectory project)
endif()
string(REPLACE "," ";" KILN_DOWNSTREAM_WAYS "${KILN_DOWNSTREAM_WAYS}")
foreach(way ${KILN_DOWNSTREAM_WAYS})
  if(NOT way MATCHES "^(package|subdirectory|project)$")
    message(FATAL_ERROR "downstream.cmake: unknown way '${way}'")
  endif()
endforeach()
string(RANDOM LENGTH 10 tag)
set(work "${KILN_BUILD_DIR}/downstream-${tag}")  # unique: two test runs may share a build
set(table "${KILN_SOURCE_DIR}/luts/ggx-dfg.exr")
# kiln's own compiler launcher (-DKILN_CXX_LAUNCHER, CTest passes CMAKE_CXX_COMPILER_LAUNCHER):
# the downstream builds compile through it too; ccache keeps the cache kiln's build uses (read
# before XDG_CACHE_HOME moves), so a run after the first finds the runtime's objects there. The
# work folder's name is new each run and the package's include folder is in it: ccache's base
# dir set to the build folder makes those paths relative, the same every run (a CCACHE_DIR set
# here also moves ccache's config file, and a base dir set there with it). The claims are about
# what the builds do, not how long they compile.
set(launcher "")
if(KILN_CXX_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${KILN_CXX_LAUNCHER})
  execute_process(COMMAND ${KILN_CXX_LAUNCHER} -k cache_dir RESULT_VARIABLE rc
                  OUTPUT_VARIABLE dir OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(rc EQUAL 0 AND dir AND NOT DEFINED ENV{CCACHE_DIR})
    set(ENV{CCACHE_DIR} "${dir}")
  endif()
  if(NOT DEFINED ENV{CCACHE_BASEDIR})
    set(ENV{CCACHE_BASEDIR} "${KILN_BUILD_DIR}")
  endif()
endif()
# The generator of the downstream builds: Ninja where it is installed (a build starts ninja and
# the compilers; Unix Makefiles start a make per target and a cmake per step besides), else the
# platform's default. The claims hold for either: kiln_bake()'s step runs when its stamp is
# missing and not when nothing changed, whatever runs it.
set(generator "")
find_program(KILN_DOWNSTREAM_NINJA ninja)
if(KILN_DOWNSTREAM_NINJA)
  set(generator -G Ninja -DCMAKE_MAKE_PROGRAM=${KILN_DOWNSTREAM_NINJA})
endif()
# A lobe that kiln_bake(MODEL_SOURCE) compiles goes into this run's own cache.
set(ENV{XDG_CACHE_HOME} "${work}/cache")

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGV}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# kiln_bake() in the package build at `dir`: the first build baked luts/fresnel-dielectric-avg.exr.
function(check_kiln_bake dir)
  set(baked "${dir}/luts/fresnel-dielectric-avg.exr")
  if(NOT EXISTS "${baked}")
    message(FATAL_ERROR "kiln_bake: ${baked} was not baked")
  endif()
  run(${KILN} sample ${baked} 1.5)
  set(want "${out}")
  run(${dir}/sample_file ${baked} 1.5)
  if(NOT out STREQUAL want OR out STREQUAL "")
    message(FATAL_ERROR "kiln_bake: sample_file printed '${out}', kiln sample '${want}'")
  endif()
  run(stat -c "%i %.9Y" ${baked})
  set(identity "${out}")
  # Nothing changed: the stamp is up to date, kiln does not run.
  run(${CMAKE_COMMAND} --build ${dir} -j 2)
  if(out MATCHES "kiln_bake\\(downstream_luts\\)")
    message(FATAL_ERROR "kiln_bake: a second build with nothing changed ran kiln again:\n${out}")
  endif()
  # The stamp removed: kiln runs, finds the table up to date and leaves the file alone.
  file(REMOVE ${dir}/downstream_luts.kiln-stamp)
  run(${CMAKE_COMMAND} --build ${dir} -j 2)
  set(log "${out}${err}")
  if(NOT log MATCHES "skipped fresnel-dielectric-avg +up to date" OR
     NOT log MATCHES "0 baked, 1 skipped")
    message(FATAL_ERROR "kiln_bake: kiln did not skip the up-to-date table:\n${log}")
  endif()
  run(stat -c "%i %.9Y" ${baked})
  if(NOT out STREQUAL identity)
    message(FATAL_ERROR "kiln_bake: the up-to-date table was rewritten (${identity} -> ${out})")
  endif()
  message(STATUS "package: kiln_bake baked once, then nothing")
  # kiln_bake(MODEL_SOURCE my_brdf.cpp TABLES my-brdf-albedo): the engine's lobe, compiled and
  # baked into a table that names it.
  set(custom "${dir}/custom_luts/my-brdf-albedo.exr")
  if(NOT EXISTS "${custom}")
    message(FATAL_ERROR "kiln_bake(MODEL_SOURCE): ${custom} was not baked")
  endif()
  run(${KILN} inspect ${custom})
  if(NOT out MATCHES "my-brdf")
    message(FATAL_ERROR "kiln_bake(MODEL_SOURCE): kiln inspect ${custom} printed:\n${out}")
  endif()
  message(STATUS "package: kiln_bake(MODEL_SOURCE) baked the engine's lobe")
endfunction()

run(${KILN} sample ${table} 0.5 0.3)
set(expected "${out}")

if("package" IN_LIST KILN_DOWNSTREAM_WAYS)
  run(${CMAKE_COMMAND} --install ${KILN_BUILD_DIR} --prefix ${work}/prefix)
  run(${work}/prefix/bin/kiln --version)
  if(NOT out MATCHES "^kiln [0-9]+\\.[0-9]+\\.[0-9]+")
    message(FATAL_ERROR "installed kiln --version printed '${out}'")
  endif()

  # Every shader snippet of runtime/shaders is installed next to the headers, byte for byte.
  file(GLOB shaders RELATIVE ${KILN_SOURCE_DIR}/runtime/shaders
       ${KILN_SOURCE_DIR}/runtime/shaders/*.glsl ${KILN_SOURCE_DIR}/runtime/shaders/*.hlsl)
  if(NOT shaders MATCHES "kiln_ltc.glsl" OR NOT shaders MATCHES "kiln_lut.hlsl")
    message(FATAL_ERROR "runtime/shaders lists '${shaders}'")
  endif()
  foreach(shader ${shaders})
    set(installed ${work}/prefix/include/kiln/shaders/${shader})
    if(NOT EXISTS ${installed})
      message(FATAL_ERROR "cmake --install did not install the shader ${shader} (${installed})")
    endif()
    file(READ ${installed} got)
    file(READ ${KILN_SOURCE_DIR}/runtime/shaders/${shader} want)
    if(NOT got STREQUAL want)
      message(FATAL_ERROR "the installed ${shader} differs from runtime/shaders/${shader}")
    endif()
  endforeach()
  message(STATUS "package: shaders installed (${shaders})")
endif()

if("project" IN_LIST KILN_DOWNSTREAM_WAYS)
  run(${CMAKE_COMMAND} -S ${KILN_SOURCE_DIR}/tests/downstream -B ${work}/project
      -DCMAKE_BUILD_TYPE=Release -DKILN_PROJECT_DIR=${KILN_SOURCE_DIR} ${generator} ${launcher})
  message(STATUS "project: configured")
endif()

foreach(way package subdirectory)
  if(NOT way IN_LIST KILN_DOWNSTREAM_WAYS)
    continue()
  endif()
  # The package way is an engine's Release build against the installed runtime; the runtime
  # folder's is an engine's Debug build, which compiles kiln's runtime sources with it (at -O0:
  # half the compile time of -O3 where no compiler cache has them yet).
  if(way STREQUAL "package")
    set(how -DCMAKE_PREFIX_PATH=${work}/prefix -DCMAKE_BUILD_TYPE=Release)
  else()
    set(how -DKILN_RUNTIME_DIR=${KILN_SOURCE_DIR}/runtime -DCMAKE_BUILD_TYPE=Debug)
  endif()
  run(${CMAKE_COMMAND} -S ${KILN_SOURCE_DIR}/tests/downstream -B ${work}/${way}
      ${how} ${generator} ${launcher})
  run(${CMAKE_COMMAND} --build ${work}/${way} -j 2)
  run(${work}/${way}/sample_in_memory)
  run(${work}/${way}/sample_file ${table} 0.5 0.3)
  if(NOT out STREQUAL expected)
    message(FATAL_ERROR "${way}: sample_file printed '${out}', kiln sample '${expected}'")
  endif()
  if(way STREQUAL "package")
    check_kiln_bake(${work}/${way})
  endif()
  message(STATUS "${way}: ok")
endforeach()
file(REMOVE_RECURSE ${work})
