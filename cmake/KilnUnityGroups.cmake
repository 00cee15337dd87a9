# kiln_unity_groups(target key): with KILN_UNITY_BUILD, the target compiles one unity source per
# group of its .cpp files (CMake's UNITY_BUILD_MODE GROUP): the headers every file of a group
# includes (the standard library, CLI11, nlohmann/json, Catch2) are parsed once for the group,
# about half the CPU time of a build from nothing. key DIR groups by folder, PREFIX by the file
# name's first word (tests/integrate_*.cpp). A file listed in KILN_UNITY_ALONE compiles alone, as
# does one with compile options of its own (-ffp-contract=off: CMake never merges those). Names in
# a file's unnamed namespace must differ from those of the other files of its group (the compiler
# says which file repeats one); -DKILN_UNITY_BUILD=OFF builds file by file.
function(kiln_unity_groups target key)
  if(NOT KILN_UNITY_BUILD)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  get_target_property(sources ${target} SOURCES)
  get_target_property(dir ${target} SOURCE_DIR)
  foreach(source ${sources})
    if(NOT source MATCHES "\\.cpp$" OR source IN_LIST KILN_UNITY_ALONE)
      continue()
    endif()
    get_filename_component(name ${source} NAME_WE)
    if(key STREQUAL "DIR")
      get_filename_component(folder ${source} DIRECTORY)
      get_filename_component(group ${folder} NAME)
    else()
      string(REGEX REPLACE "_.*" "" group ${name})
    endif()
    set_source_files_properties(${source} DIRECTORY ${dir} PROPERTIES UNITY_GROUP ${target}_${group})
  endforeach()
endfunction()
