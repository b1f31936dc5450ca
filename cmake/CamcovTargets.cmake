# One library per stage of the data flow. A stage links only the stages below it, so an
# include that points the wrong way fails to link instead of slipping through review.
#
#   camcov_add_stage(NAME <stage> SOURCES ... DEPENDS ...)  -> library camcov_<stage>
#   camcov_add_test(NAME <stage> SOURCES ... DEPENDS ...)   -> test binary test_<stage>
function(camcov_add_stage)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPENDS" ${ARGN})
  add_library(camcov_${ARG_NAME} STATIC ${ARG_SOURCES})
  target_include_directories(camcov_${ARG_NAME} PUBLIC
    ${PROJECT_SOURCE_DIR}/src ${PROJECT_BINARY_DIR}/generated)
  target_link_libraries(camcov_${ARG_NAME} PUBLIC ${ARG_DEPENDS})
endfunction()

function(camcov_add_test)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;DEPENDS" ${ARGN})
  add_executable(test_${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(test_${ARG_NAME} PRIVATE ${ARG_DEPENDS} GTest::gtest GTest::gtest_main)
  target_compile_definitions(test_${ARG_NAME} PRIVATE
    CAMCOV_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data"
    CAMCOV_SCENES_DIR="${PROJECT_SOURCE_DIR}/scenes"
    CAMCOV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(test_${ARG_NAME} DISCOVERY_TIMEOUT 60
    PROPERTIES ENVIRONMENT "CAMCOV_BINARY=$<TARGET_FILE:camcov>")
endfunction()
