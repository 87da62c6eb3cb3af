# Configure, build and run the consumer against a softgrasp build tree.
# Invoked by CTest with -DSOURCE_DIR, -DBINARY_DIR, -Dsoftgrasp_DIR.
file(REMOVE_RECURSE ${BINARY_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BINARY_DIR}
                  -Dsoftgrasp_DIR=${softgrasp_DIR}
                  -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "configuring the consumer failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR}
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "building the consumer failed")
endif()
execute_process(COMMAND ${BINARY_DIR}/consumer RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the consumer program failed")
endif()
