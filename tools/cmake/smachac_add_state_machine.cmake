# smachac_add_state_machine(<target> SCRIPT <script.yml>
#                           [TEMPLATE_DIRS <dir>...] [SCRIPT_DIRS <dir>...]
#                           [OPTIONS <smachac option>...])
#
# Compiles a SMACHA script to C++ at build time (`smachac -target=cpp`) and builds it as the
# executable <target>, linked with the smachac runtime (smachac::runtime). The generated file
# is <binary dir>/<target>.smachac.cpp; smachac writes a depfile listing the script, every
# sub-script it read and the files of the TEMPLATE_DIRS, so editing any of them regenerates
# the program. TEMPLATE_DIRS are passed as -I (searched before the built-in C++ templates),
# SCRIPT_DIRS as --script-dir. Relative paths are relative to the calling CMakeLists.txt.
#
# Works in the smachac tree (the `smachac` and `smachac_runtime` targets) and with an
# installed smachac (find_package(smachac) defines the imported targets smachac::smachac and
# smachac::runtime).
include_guard(GLOBAL)

function(_smachac_absolute_paths out_var)
  set(result "")
  foreach(path IN LISTS ARGN)
    get_filename_component(abs "${path}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND result "${abs}")
  endforeach()
  set(${out_var} "${result}" PARENT_SCOPE)
endfunction()

function(_smachac_compiler out_var)
  if(TARGET smachac)
    set(${out_var} "$<TARGET_FILE:smachac>" PARENT_SCOPE)
  elseif(TARGET smachac::smachac)
    set(${out_var} "$<TARGET_FILE:smachac::smachac>" PARENT_SCOPE)
  else()
    find_program(SMACHAC_EXECUTABLE smachac REQUIRED)
    set(${out_var} "${SMACHAC_EXECUTABLE}" PARENT_SCOPE)
  endif()
endfunction()

function(smachac_add_state_machine target)
  cmake_parse_arguments(SASM "" "SCRIPT" "TEMPLATE_DIRS;SCRIPT_DIRS;OPTIONS" ${ARGN})
  if(NOT SASM_SCRIPT)
    message(FATAL_ERROR "smachac_add_state_machine(${target}): SCRIPT is required")
  endif()
  _smachac_absolute_paths(script "${SASM_SCRIPT}")
  _smachac_absolute_paths(template_dirs ${SASM_TEMPLATE_DIRS})
  _smachac_absolute_paths(script_dirs ${SASM_SCRIPT_DIRS})
  _smachac_compiler(compiler)

  set(output "${CMAKE_CURRENT_BINARY_DIR}/${target}.smachac.cpp")
  set(depfile "${CMAKE_CURRENT_BINARY_DIR}/${target}.smachac.d")
  set(args -target=cpp "${script}" -o "${output}" "--depfile=${depfile}" ${SASM_OPTIONS})
  foreach(dir IN LISTS template_dirs)
    list(APPEND args -I "${dir}")
  endforeach()
  foreach(dir IN LISTS script_dirs)
    list(APPEND args "--script-dir=${dir}")
  endforeach()
  set(compiler_dep "")
  if(TARGET smachac)
    set(compiler_dep smachac)
  endif()

  add_custom_command(
    OUTPUT "${output}"
    COMMAND ${compiler} ${args}
    DEPENDS "${script}" ${compiler_dep}
    DEPFILE "${depfile}"
    WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
    COMMENT "smachac -target=cpp ${SASM_SCRIPT}"
    VERBATIM)
  add_executable(${target} "${output}")
  target_compile_features(${target} PRIVATE cxx_std_20)
  if(TARGET smachac_runtime)
    target_link_libraries(${target} PRIVATE smachac_runtime)
  else()
    target_link_libraries(${target} PRIVATE smachac::runtime)
  endif()
endfunction()
