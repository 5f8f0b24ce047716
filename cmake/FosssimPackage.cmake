# Install rules and the FOSSSim CMake package: after `cmake --install build --prefix P`, another
# project finds the libraries with
#     find_package(FOSSSim 0.1 REQUIRED)
#     target_link_libraries(app PRIVATE fosssim::io)   # or fosssim::core, fosssim::render, ...
# Components: Runtime (the FOSSSim program), Development (libraries, public headers, package
# files). The Python module installs its own component (python/CMakeLists.txt), so a wheel holds
# the module only.
include(CMakePackageConfigHelpers)

# The public headers: what a program needs to build or load a scene, step it, read diagnostics,
# write and grade trajectories, and draw it; plus the headers these include (tests/package builds
# a program that includes each of them against the installed package, so a public header that
# includes a private one fails there). Everything else under include/ is the project's own.
set(FOSSSIM_PUBLIC_HEADERS
  core/collision_handler.h core/collision_log.h core/force.h core/forces.h core/integrator.h
  core/scene.h core/scene_values.h core/simulator.h core/state.h core/status.h core/step_stats.h core/types.h
  core/verify.h
  io/grader.h io/scene_file.h io/trajectory.h
  # The leaf library (fosssim::math): polynomials, the interval solver ("the first t in [0, 1]
  # at which all these polynomials are positive"), continuous collision detection, geometry and
  # the failsafe's projections. It knows nothing of scenes and needs only Eigen.
  math/ccd.h math/ccd_exact.h math/contact_projector.h math/contract.h math/exact_solve_limits.h math/geometry.h
  math/interval_solver.h math/polynomial.h math/real_roots.h math/zone_projection.h)
if(EXISTS ${PROJECT_SOURCE_DIR}/include/fosssim/io/scene_writer.h)
  list(APPEND FOSSSIM_PUBLIC_HEADERS io/scene_writer.h)
endif()
if(EXISTS ${PROJECT_SOURCE_DIR}/include/fosssim/core/diagnostics.h)
  list(APPEND FOSSSIM_PUBLIC_HEADERS core/diagnostics.h)
endif()
# The picture (camera, trails, shapes) and its SVG writer need no OpenGL; raster frames and PNG
# files only exist with the renderer.
list(APPEND FOSSSIM_PUBLIC_HEADERS render/camera.h render/image.h render/path_trails.h render/picture.h
                                   render/svg_writer.h)
set(fosssim_exported fosssim_math fosssim_core fosssim_io fosssim_picture)
if(TARGET fosssim_render)
  list(APPEND FOSSSIM_PUBLIC_HEADERS render/offscreen_renderer.h render/png_writer.h)
  list(APPEND fosssim_exported fosssim_render)
endif()

foreach(header ${FOSSSIM_PUBLIC_HEADERS})
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/include/fosssim/${header}
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/fosssim/${folder} COMPONENT Development)
endforeach()

install(TARGETS ${fosssim_exported} EXPORT FOSSSimTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS FOSSSim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)

set(FOSSSIM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/FOSSSim)
install(EXPORT FOSSSimTargets NAMESPACE fosssim:: DESTINATION ${FOSSSIM_CMAKE_DIR} COMPONENT Development)

# What the config must find again: the libraries are static, so their private dependencies
# (tinyxml2, the renderer's GL stack) are linked by the consumer.
# (find_package results are local to src/core, so ask the target what it links.)
get_target_property(fosssim_core_links fosssim_core LINK_LIBRARIES)
set(FOSSSIM_WITH_OPENMP OFF)
if("OpenMP::OpenMP_CXX" IN_LIST fosssim_core_links)
  set(FOSSSIM_WITH_OPENMP ON)
endif()
set(FOSSSIM_WITH_RENDER OFF)
if(TARGET fosssim_render)
  set(FOSSSIM_WITH_RENDER ON)
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/FOSSSimConfig.cmake.in
  ${PROJECT_BINARY_DIR}/FOSSSimConfig.cmake INSTALL_DESTINATION ${FOSSSIM_CMAKE_DIR})
# 0.x: a minor version may change the interface, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/FOSSSimConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/FOSSSimConfig.cmake ${PROJECT_BINARY_DIR}/FOSSSimConfigVersion.cmake
        DESTINATION ${FOSSSIM_CMAKE_DIR} COMPONENT Development)
