# smachac_embed_files(<target> NAMESPACE <ns> FUNCTION <fn> BASE_DIR <dir> FILES <files...>)
#
# Builds a static library <target> with one function
#   std::span<const smachac::EmbeddedFile> <ns>::<fn>();
# listing every file (path relative to BASE_DIR, bytes) in the order given. The generated
# source is rebuilt whenever one of the files changes. Used to embed templates/ into the
# compiler so that a built binary needs no data files. The calling folder is the library's
# include root (its header declares <fn>).
function(smachac_embed_files target)
  cmake_parse_arguments(EMB "" "NAMESPACE;FUNCTION;BASE_DIR" "FILES" ${ARGN})
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded.cpp")
  set(list_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_files.txt")
  string(REPLACE ";" "\n" files_text "${EMB_FILES}")
  file(WRITE "${list_file}.in" "${files_text}")
  configure_file("${list_file}.in" "${list_file}" COPYONLY)
  add_custom_command(
    OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DLIST=${list_file} -DBASE=${EMB_BASE_DIR}
            -DNS=${EMB_NAMESPACE} -DFN=${EMB_FUNCTION}
            -P "${PROJECT_SOURCE_DIR}/tools/cmake/embed_files_gen.cmake"
    DEPENDS ${EMB_FILES} "${list_file}" "${PROJECT_SOURCE_DIR}/tools/cmake/embed_files_gen.cmake"
    COMMENT "Embedding ${target}"
    VERBATIM)
  add_library(${target} STATIC "${out}")
  file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
  smachac_include_root(${target} "${folder}")  # the folder's header declares the function
  target_link_libraries(${target} PUBLIC smachac_support)
endfunction()
