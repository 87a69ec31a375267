# Configures and builds the clang fuzz project (run by the fuzz_gemdb_build CTest step).
foreach(var SOURCE BINARY CXX ENGINE GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "build_fuzzer.cmake: -D${var}= is required")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G ${GENERATOR}
                        -DCMAKE_CXX_COMPILER=${CXX} -DGEM_ENGINE_DIR=${ENGINE}
                RESULT_VARIABLE configured)
if(NOT configured EQUAL 0)
  message(FATAL_ERROR "configuring the fuzz project failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY} -j 2 RESULT_VARIABLE built)
if(NOT built EQUAL 0)
  message(FATAL_ERROR "building the fuzz target failed")
endif()
