# smachac_add_state_machine(<target> SCRIPT <script.yml> [LIBRARY]
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
# With LIBRARY, <target> is a static library instead (`smachac -target=cpp -emit=library`):
# <binary dir>/smachac_<target>/<target>.h and .cpp, the header on the target's public include
# path and the runtime linked publicly. A program links it and writes
#   #include "<target>.h"
#   auto machine = <target>::build();   // std::unique_ptr<smachac::runtime::StateMachine>
# (the namespace is <target> made a C++ identifier: `-` and other characters become `_`).
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
  cmake_parse_arguments(SASM "LIBRARY" "SCRIPT" "TEMPLATE_DIRS;SCRIPT_DIRS;OPTIONS" ${ARGN})
  if(NOT SASM_SCRIPT)
    message(FATAL_ERROR "smachac_add_state_machine(${target}): SCRIPT is required")
  endif()
  _smachac_absolute_paths(script "${SASM_SCRIPT}")
  _smachac_absolute_paths(template_dirs ${SASM_TEMPLATE_DIRS})
  _smachac_absolute_paths(script_dirs ${SASM_SCRIPT_DIRS})
  _smachac_compiler(compiler)

  set(output "${CMAKE_CURRENT_BINARY_DIR}/${target}.smachac.cpp")
  set(outputs "${output}")
  set(depfile "${CMAKE_CURRENT_BINARY_DIR}/${target}.smachac.d")
  set(args -target=cpp "${script}")
  set(emit_option "")
  if(SASM_LIBRARY)
    set(emit_option "-emit=library ")
    set(include_dir "${CMAKE_CURRENT_BINARY_DIR}/smachac_${target}")
    file(MAKE_DIRECTORY "${include_dir}")
    set(output "${include_dir}/${target}.cpp")
    set(outputs "${output}" "${include_dir}/${target}.h")
    list(APPEND args -emit=library)
  endif()
  list(APPEND args -o "${output}" "--depfile=${depfile}" ${SASM_OPTIONS})
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
    OUTPUT ${outputs}
    COMMAND ${compiler} ${args}
    DEPENDS "${script}" ${compiler_dep}
    DEPFILE "${depfile}"
    WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
    COMMENT "smachac -target=cpp ${emit_option}${SASM_SCRIPT}"
    VERBATIM)
  set(visibility PRIVATE)
  if(SASM_LIBRARY)
    add_library(${target} STATIC ${outputs})
    target_include_directories(${target} PUBLIC "${include_dir}")
    set(visibility PUBLIC)
  else()
    add_executable(${target} "${output}")
  endif()
  target_compile_features(${target} ${visibility} cxx_std_20)
  if(TARGET smachac_runtime)
    target_link_libraries(${target} ${visibility} smachac_runtime)
  else()
    target_link_libraries(${target} ${visibility} smachac::runtime)
  endif()
endfunction()
