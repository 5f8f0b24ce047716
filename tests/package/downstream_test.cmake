# Run by ctest (tests/package/CMakeLists.txt): installs the FOSSSim build FOSSSIM_BUILD into a
# fresh prefix under $TMPDIR (else under the build directory), then configures, builds and runs
# the downstream project against that prefix alone. The temporary folder is removed at the end,
# also after a failure.
foreach(var FOSSSIM_BUILD DOWNSTREAM_SOURCE GENERATOR CXX_COMPILER SCENE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "downstream_test.cmake: -D${var}=... missing")
  endif()
endforeach()

if(DEFINED ENV{TMPDIR} AND IS_DIRECTORY "$ENV{TMPDIR}")
  set(base "$ENV{TMPDIR}")
else()
  set(base "${FOSSSIM_BUILD}/tmp")
endif()
string(RANDOM LENGTH 8 suffix)
set(work "${base}/fosssim-package-${suffix}")
file(MAKE_DIRECTORY "${work}")

function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    file(REMOVE_RECURSE "${work}")
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

step("install" ${CMAKE_COMMAND} --install "${FOSSSIM_BUILD}" --prefix "${work}/prefix")

# Only the public headers are installed: exactly the list, nothing from math/ or the internals.
file(GLOB_RECURSE installed RELATIVE "${work}/prefix/include/fosssim" "${work}/prefix/include/fosssim/*")
list(SORT installed)
string(REPLACE "," ";" expected "${HEADERS}")
list(SORT expected)
if(NOT installed STREQUAL expected)
  file(REMOVE_RECURSE "${work}")
  message(FATAL_ERROR "installed headers differ from the public list:\n installed: ${installed}\n expected:  ${expected}")
endif()

set(flags)
set(build_type Release)
if(SANITIZE)
  # The installed libraries were built with sanitizers (Debug): the program is compiled the same
  # way, since inline code of the public headers (destructors of scene members) compiled without
  # the sanitizer and freed by it is reported as a bad free.
  set(build_type Debug)
  list(APPEND flags "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined -fno-omit-frame-pointer"
       "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()
step("configure" ${CMAKE_COMMAND} -S "${DOWNSTREAM_SOURCE}" -B "${work}/build" -G "${GENERATOR}"
     -DCMAKE_BUILD_TYPE=${build_type} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
     "-DCMAKE_PREFIX_PATH=${work}/prefix" -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON
     "-DFOSSSIM_HEADERS=${HEADERS}" ${flags})
step("build" ${CMAKE_COMMAND} --build "${work}/build" -j 1)
step("run" "${work}/build/downstream" "${SCENE}")
message(STATUS "${last_output}")
# The installed program runs too.
step("installed FOSSSim" "${work}/prefix/bin/FOSSSim" -s "${SCENE}" -d 0 -q)
file(REMOVE_RECURSE "${work}")
