# tmop_module(NAME DEPS dep...) makes the static library target tmop_NAME_lib (libtmop_NAME.a) from tmop/NAME/*.cc
# (an INTERFACE library while the folder has only headers). One library per concept folder
# keeps the dependency direction of docs/architecture.md checkable by the linker.
function(tmop_module name)
  cmake_parse_arguments(M "" "" "DEPS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tmop/${name}/*.cc)
  set(lib tmop_${name}_lib)
  if(srcs)
    add_library(${lib} STATIC ${srcs})
    set_target_properties(${lib} PROPERTIES OUTPUT_NAME tmop_${name})
    target_include_directories(${lib} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                             $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    target_link_libraries(${lib} PUBLIC ${M_DEPS} PRIVATE $<BUILD_INTERFACE:tmop_warnings>)
  else()
    add_library(${lib} INTERFACE)
    target_include_directories(${lib} INTERFACE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                                $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    target_link_libraries(${lib} INTERFACE ${M_DEPS})
  endif()
  install(TARGETS ${lib} EXPORT tmopTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()

# tmop_test(MODULE LIBS lib...) makes tmop_MODULE_tests from tests/MODULE/*_test.cc and registers
# every test case with ctest.
function(tmop_test module)
  cmake_parse_arguments(T "" "" "LIBS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tests/${module}/*.cc)
  if(NOT srcs)
    return()
  endif()
  set(exe tmop_${module}_tests)
  add_executable(${exe} ${srcs})
  target_link_libraries(${exe} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main tmop_warnings)
  target_include_directories(${exe} PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_definitions(${exe} PRIVATE TMOP_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                            TMOP_BINARY_DIR="${PROJECT_BINARY_DIR}")
  gtest_discover_tests(${exe} WORKING_DIRECTORY ${PROJECT_BINARY_DIR} DISCOVERY_TIMEOUT 60
                       PROPERTIES LABELS ${module})
endfunction()
