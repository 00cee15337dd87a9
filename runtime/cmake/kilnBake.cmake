# kiln_bake(): bake kiln lookup tables as a step of an engine's build.
#
#   kiln_bake(TARGET <name> OUT <dir>
#             [TABLES <table>...]     # catalogue tables (kiln bake --only); default: all of them
#             [SCENE <file>]          # or what a glTF / kiln scene needs (kiln bake --scene)
#             [SIZE <n>]              # kiln bake --size
#             [FORMAT <format>]       # kiln bake --format, passed only when given
#             [MODEL_SOURCE <file>...] # a user's lobe (kiln/model_abi.h), kiln bake --model-source
#             [ARGS <arg>...])        # any other `kiln bake` arguments (-j 2, --header, ...)
#
# Adds the target <name> (built by default, `ALL`) that runs `kiln bake --out <dir> ...` through
# a custom command whose output is a stamp file, <binary dir>/<name>.kiln-stamp. The command runs
# again when the kiln executable, the scene file, a MODEL_SOURCE file or the arguments change (or
# the stamp is deleted); kiln then skips every table whose file in <dir> is up to date (same spec
# hash, same pixel type, manifest entry present) and bakes only the missing and stale ones. A
# build with nothing changed runs nothing. A relative OUT is taken from the current binary dir, a
# relative SCENE or MODEL_SOURCE from the current source dir. A MODEL_SOURCE lobe's tables are
# named in TABLES (<id>-albedo, <id>-albedo-avg, <id>-dfg) or by the SCENE; an edited lobe makes
# them stale (its hash is in their spec hash), so the next build re-bakes them. The kiln
# executable is the target kiln::kiln: imported by find_package(kiln), or built when kiln's
# project is added with add_subdirectory.
include_guard(GLOBAL)

function(kiln_bake)
  cmake_parse_arguments(PARSE_ARGV 0 KB "" "TARGET;OUT;SCENE;SIZE;FORMAT"
                        "TABLES;ARGS;MODEL_SOURCE")
  if(KB_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "kiln_bake: unknown arguments: ${KB_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT KB_TARGET OR NOT KB_OUT)
    message(FATAL_ERROR "kiln_bake: TARGET and OUT are required")
  endif()
  if(KB_TABLES AND KB_SCENE)
    message(FATAL_ERROR "kiln_bake(${KB_TARGET}): give TABLES or SCENE, not both")
  endif()
  if(NOT TARGET kiln::kiln)
    message(FATAL_ERROR "kiln_bake(${KB_TARGET}): no kiln::kiln target: use find_package(kiln) "
                        "with kiln installed, or add_subdirectory of the kiln project (not only "
                        "of its runtime/ folder)")
  endif()
  get_filename_component(out "${KB_OUT}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  set(args bake --out "${out}")
  set(depends "")
  if(KB_TABLES)
    list(JOIN KB_TABLES "," only)
    list(APPEND args --only "${only}")
  endif()
  if(KB_SCENE)
    get_filename_component(scene "${KB_SCENE}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND args --scene "${scene}")
    list(APPEND depends "${scene}")
  endif()
  foreach(source IN LISTS KB_MODEL_SOURCE)
    get_filename_component(source "${source}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND args --model-source "${source}")
    list(APPEND depends "${source}")
  endforeach()
  if(DEFINED KB_SIZE)
    list(APPEND args --size "${KB_SIZE}")
  endif()
  if(DEFINED KB_FORMAT)
    list(APPEND args --format "${KB_FORMAT}")
  endif()
  list(APPEND args ${KB_ARGS})

  # The arguments, in a file rewritten only when they change: the command re-runs then too.
  set(stamp "${CMAKE_CURRENT_BINARY_DIR}/${KB_TARGET}.kiln-stamp")
  set(argsFile "${CMAKE_CURRENT_BINARY_DIR}/${KB_TARGET}.kiln-args")
  string(REPLACE ";" "\n" argsText "${args}")
  file(CONFIGURE OUTPUT "${argsFile}" CONTENT "${argsText}\n" @ONLY)
  list(APPEND depends "${argsFile}")

  # The executable: a file dependency on it (the command re-runs when kiln is rebuilt or
  # reinstalled) and, when kiln is built in this project, a target dependency too.
  get_target_property(kilnTarget kiln::kiln ALIASED_TARGET)
  if(kilnTarget)
    list(APPEND depends ${kilnTarget})
  else()
    list(APPEND depends "$<TARGET_FILE:kiln::kiln>")
  endif()

  add_custom_command(
    OUTPUT "${stamp}"
    COMMAND "$<TARGET_FILE:kiln::kiln>" ${args}
    COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}"
    DEPENDS ${depends}
    COMMENT "kiln_bake(${KB_TARGET}): baking the missing and stale tables into ${out}"
    VERBATIM)
  add_custom_target(${KB_TARGET} ALL DEPENDS "${stamp}")
  set_property(TARGET ${KB_TARGET} PROPERTY KILN_OUT "${out}")
endfunction()
