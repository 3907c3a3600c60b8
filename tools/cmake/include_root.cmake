# smachac_include_root(<target> <folder>)
#
# Gives <target> the one include root it exports: "<folder>/x.h" resolves through a mirror
# of <folder> in the build tree (symbolic links to the sources) that holds <folder>'s own
# files and sub-folders but not the folders of the other libraries nested in it (listed in
# SMACHAC_LIBRARY_FOLDERS). So a library sees the headers of itself and of what it links,
# and nothing else: an #include that goes up or sideways does not compile. Folders are
# listed with CONFIGURE_DEPENDS, so a new header re-runs CMake at the next build.

# Every folder that is its own library, as the #include paths name it.
set(SMACHAC_LIBRARY_FOLDERS
    ir/support ir frontend passes refactor checker lsp templates
    backends/tmpl backends/generator backends tools/smachac)

function(smachac_include_root target folder)
  set(root "${PROJECT_BINARY_DIR}/include_roots/${target}")
  file(REMOVE_RECURSE "${root}")
  _smachac_mirror_folder("${folder}" "${root}")
  target_include_directories(${target} PUBLIC "${root}")
endfunction()

# Mirrors <folder> (relative to the project root) under <root>, skipping nested libraries.
function(_smachac_mirror_folder folder root)
  file(MAKE_DIRECTORY "${root}/${folder}")
  file(GLOB entries CONFIGURE_DEPENDS LIST_DIRECTORIES true RELATIVE "${PROJECT_SOURCE_DIR}"
       "${PROJECT_SOURCE_DIR}/${folder}/*")
  foreach(entry IN LISTS entries)
    if(entry IN_LIST SMACHAC_LIBRARY_FOLDERS)
      continue()
    endif()
    _smachac_holds_library("${entry}" holds_library)
    if(holds_library)
      _smachac_mirror_folder("${entry}" "${root}")
    else()
      file(CREATE_LINK "${PROJECT_SOURCE_DIR}/${entry}" "${root}/${entry}" SYMBOLIC)
    endif()
  endforeach()
endfunction()

# Whether the folder <entry> contains the folder of another library.
function(_smachac_holds_library entry result)
  set(${result} FALSE PARENT_SCOPE)
  foreach(library_folder IN LISTS SMACHAC_LIBRARY_FOLDERS)
    string(FIND "${library_folder}" "${entry}/" position)
    if(position EQUAL 0)
      set(${result} TRUE PARENT_SCOPE)
    endif()
  endforeach()
endfunction()
