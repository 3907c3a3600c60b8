# Runs one generated Baxter experiment program and checks what it printed (ctest, label `sim`):
#   cmake -DPROGRAM=<exe> -DVERDICT=stacked|placed [-DPLACE=x,y,z] -P check_experiment.cmake
# The program runs with --robot-quiet (no robot log) and prints `outcome: <o>` and the scene
# report (runBaxter). Checks: exit code 0, outcome succeeded, and
#   stacked  the report's verdict line `stacked: ...` (|dxy| < 15 mm, |dz - 0.05| < 5 mm,
#            judged by the robot report)
#   placed   block1's centre within 10 mm of PLACE (base frame, metres) on every axis
cmake_minimum_required(VERSION 3.25)

execute_process(COMMAND "${PROGRAM}" --robot-quiet
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} exited with ${code}\n${err}")
endif()
if(NOT out MATCHES "outcome: succeeded\n")
  message(FATAL_ERROR "outcome is not succeeded\n${err}")
endif()

# "0.7512", "-0.13", "1" -> tenths of a millimetre as an integer (7512, -1300, 10000).
function(tenth_mm text out_var)
  if(NOT text MATCHES "^(-?)([0-9]+)(\\.([0-9]*))?$")
    message(FATAL_ERROR "not a number: ${text}")
  endif()
  set(sign "${CMAKE_MATCH_1}")
  set(whole "${CMAKE_MATCH_2}")
  string(SUBSTRING "${CMAKE_MATCH_4}0000" 0 4 fraction)
  math(EXPR value "${sign}${whole}${fraction}")  # leading zeros are decimal, not octal
  set(${out_var} "${value}" PARENT_SCOPE)
endfunction()

if(VERDICT STREQUAL "stacked")
  if(NOT out MATCHES "\n  (stacked: [^\n]*)")
    message(FATAL_ERROR "the report does not say stacked")
  endif()
  message("verdict: ${CMAKE_MATCH_1}")
elseif(VERDICT STREQUAL "placed")
  set(number "(-?[0-9]+\\.[0-9]+)")
  if(NOT out MATCHES "block1 at \\(${number}, ${number}, ${number}\\)")
    message(FATAL_ERROR "the report gives no position of block1")
  endif()
  set(actual "${CMAKE_MATCH_1};${CMAKE_MATCH_2};${CMAKE_MATCH_3}")
  string(REPLACE "," ";" expected "${PLACE}")
  foreach(i RANGE 2)
    list(GET actual ${i} a)
    list(GET expected ${i} e)
    tenth_mm("${a}" a10)
    tenth_mm("${e}" e10)
    math(EXPR diff "${a10} - ${e10}")
    if(diff LESS -100 OR diff GREATER 100)
      message(FATAL_ERROR "block1 at (${actual}) is not within 10 mm of (${PLACE})")
    endif()
  endforeach()
  message("verdict: block1 placed within 10 mm of (${PLACE})")
else()
  message(FATAL_ERROR "VERDICT must be stacked or placed")
endif()
