# smachac_embed_files(<target> [TOKENS] [IMAGES] NAMESPACE <ns> FUNCTION <fn> BASE_DIR <dir>
#                     FILES <files...>)
#
# Builds a static library <target> with one function
#   std::span<const smachac::EmbeddedFile> <ns>::<fn>();
# listing every file (path relative to BASE_DIR, bytes) in the order given; with TOKENS, also
# each file's tokens as the template engine lexes it (the files are templates; one that does
# not lex fails the build); with IMAGES, also each template's parsed and analysed image
# (backends/tmpl/image/image_format.h), compiled with the filters of its set (the first folder
# of its path: target_extensions.h). The generator is embed_gen.cpp; the generated source is rebuilt
# whenever one of the files changes. Used to embed templates/ into the
# compiler so that a built binary needs no data files. The calling folder is the library's
# include root (its header declares <fn>).
function(smachac_embed_files target)
  cmake_parse_arguments(EMB "TOKENS;IMAGES" "NAMESPACE;FUNCTION;BASE_DIR" "FILES" ${ARGN})
  if(NOT TARGET smachac_embed_gen)
    # The targets' filter files are compiled into the tool itself (as for meta_table_gen):
    # smachac_backends links the embedded table this tool writes.
    add_executable(smachac_embed_gen "${PROJECT_SOURCE_DIR}/tools/cmake/embed_gen.cpp"
                   "${PROJECT_SOURCE_DIR}/backends/smach/python_extensions.cpp"
                   "${PROJECT_SOURCE_DIR}/backends/smach/python_code.cpp"
                   "${PROJECT_SOURCE_DIR}/backends/cpp/cpp_extensions.cpp")
    target_include_directories(smachac_embed_gen PRIVATE "${PROJECT_SOURCE_DIR}")
    target_link_libraries(smachac_embed_gen PRIVATE smachac_generator smachac_tmpl)
  endif()
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded.cpp")
  # The list of files as a dependency: adding or removing one regenerates the table.
  set(list_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_files.txt")
  string(REPLACE ";" "\n" files_text "${EMB_FILES}")
  file(WRITE "${list_file}.in" "${files_text}")
  configure_file("${list_file}.in" "${list_file}" COPYONLY)
  set(tokens_flag "")
  if(EMB_TOKENS)
    list(APPEND tokens_flag "--tokens")
  endif()
  if(EMB_IMAGES)
    list(APPEND tokens_flag "--images")
  endif()
  # The generator rewrites the source only when it changes (nothing recompiles after a rebuilt
  # generator that writes the same table); the stamp records that it ran.
  set(stamp "${out}.stamp")
  add_custom_command(
    OUTPUT "${stamp}"
    BYPRODUCTS "${out}"
    COMMAND smachac_embed_gen "${out}" ${EMB_NAMESPACE} ${EMB_FUNCTION} "${EMB_BASE_DIR}"
            ${tokens_flag} ${EMB_FILES}
    COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}"
    DEPENDS smachac_embed_gen ${EMB_FILES} "${list_file}"
    COMMENT "Embedding ${target}"
    VERBATIM)
  add_library(${target} STATIC "${out}" "${stamp}")
  file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
  smachac_include_root(${target} "${folder}")  # the folder's header declares the function
  target_link_libraries(${target} PUBLIC smachac_support)
endfunction()
