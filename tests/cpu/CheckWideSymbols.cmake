# WideShadingSymbolsTest: the AVX2 kernel's object file may define no symbol
# another translation unit could also define (an inline function or a
# template on plain float), or the linker could keep its AVX2 copy for
# callers that run on CPUs without AVX2. Every global symbol it defines
# must name the AVX2 architecture (or be the C++ runtime's personality ref).
#   cmake -DOBJECTS=<objects of shadinglab_cpu> -DNM=<nm> -P CheckWideSymbols.cmake
set(avx2_object "")
foreach(o IN LISTS OBJECTS)
  if(o MATCHES "WideShadingAvx2\\.cpp\\.o$")
    set(avx2_object "${o}")
  endif()
endforeach()
if(NOT avx2_object)
  message(FATAL_ERROR "WideShadingAvx2.cpp.o is not among the objects: ${OBJECTS}")
endif()
execute_process(COMMAND ${NM} -C --defined-only --extern-only "${avx2_object}"
  OUTPUT_VARIABLE symbols RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nm failed on ${avx2_object}")
endif()
string(REPLACE "\n" ";" lines "${symbols}")
set(bad "")
set(count 0)
foreach(line IN LISTS lines)
  if(line STREQUAL "")
    continue()
  endif()
  math(EXPR count "${count} + 1")
  if(NOT line MATCHES "[aA][vV][xX]2" AND NOT line MATCHES "DW\\.ref\\.__gxx_personality_v0")
    string(APPEND bad "  ${line}\n")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "the AVX2 kernel defines symbols other code may share:\n${bad}")
endif()
message(STATUS "${count} global symbols in ${avx2_object}, every one the AVX2 kernel's own")
