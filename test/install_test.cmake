# Installs SpectralSeg into a temporary prefix as a user would, and builds the
# README's example project (test/install_consumer) against it.
# Invoked by CTest with -DSOURCE_DIR=... -DBUILD_DIR=... -DWORK=... -DDATA=...
# -DVERSION=... -DGENERATOR=... -DTOOL=<path of the built tool, or empty>
# -DWITH_TBB=... -DWITH_EMBREE=... -DWITH_RENDERING=... -DWITH_LIBMAXFLOW=...
#
# Checks, each of which failed before install worked from any configure:
# 1. `cmake --install` of this build installs the headers, the package
#    files, the tool and the reference manual (when built);
# 2. `cmake --install` right after a configure (nothing built) succeeds and
#    installs the header-only package without the tool;
# 3. the package config asks for TBB and Embree only QUIETly: a consumer
#    without them configures; REQUIRED COMPONENTS TBB then fails;
# 4. the README's usage code is the code of test/install_consumer;
# 5. that project builds against the installed package (without TBB and
#    Embree) and segments a mesh.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(failures 0)

function(fail what)
  message("FAIL: ${what}")
  math(EXPR n "${failures} + 1")
  set(failures ${n} PARENT_SCOPE)
endfunction()

# runs a command; sets `out` (stdout and stderr) and `rc` in the caller
macro(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out TIMEOUT 900)
  string(REPLACE ";" " " _command "${ARGN}")
  message("$ ${_command}  -> ${rc}")
endmacro()

# The consumer projects find the CGAL of this build (CGAL_DIR; a CGAL 6
# build without gmpxx, CGAL_WITH_GMPXX=OFF, too).
set(cgal_args "")
if(CGAL_DIR)
  list(APPEND cgal_args -DCGAL_DIR=${CGAL_DIR})
endif()
if(NOT "${CGAL_WITH_GMPXX}" STREQUAL "")
  list(APPEND cgal_args -DCGAL_WITH_GMPXX=${CGAL_WITH_GMPXX})
endif()

# 1. this build, installed
set(prefix ${WORK}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
if(NOT rc EQUAL 0)
  fail("cmake --install of the build: ${out}")
endif()
set(expected include/SpectralSeg/version.h include/SpectralSeg/k_way_segmentation.h
             include/SpectralSeg/IO/write_segmented_mesh.h lib/cmake/SpectralSeg/SpectralSegConfig.cmake
             lib/cmake/SpectralSeg/SpectralSegConfigVersion.cmake lib/cmake/SpectralSeg/SpectralSegTargets.cmake)
if(TOOL)
  list(APPEND expected bin/spectralseg)
endif()
if(EXISTS ${BUILD_DIR}/doc/html/index.html)
  list(APPEND expected share/doc/SpectralSeg/html/index.html)
endif()
foreach(f ${expected})
  if(NOT EXISTS ${prefix}/${f})
    fail("not installed: ${f}")
  endif()
endforeach()
if(TOOL)
  run(${prefix}/bin/spectralseg --version)
  if(NOT out STREQUAL "spectralseg ${VERSION}\n")
    fail("the installed tool says '${out}', expected 'spectralseg ${VERSION}'")
  endif()
endif()

# 2. install after a configure only: the package, no tool, no failure
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK}/configured_only -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release ${cgal_args})
if(NOT rc EQUAL 0)
  fail("configure of a fresh build tree: ${out}")
endif()
run(${CMAKE_COMMAND} --install ${WORK}/configured_only --prefix ${WORK}/prefix_configured_only)
if(NOT rc EQUAL 0)
  fail("cmake --install without a build must install the header-only package: ${out}")
endif()
if(NOT EXISTS ${WORK}/prefix_configured_only/lib/cmake/SpectralSeg/SpectralSegConfig.cmake
   OR NOT EXISTS ${WORK}/prefix_configured_only/include/SpectralSeg/version.h)
  fail("cmake --install without a build did not install the package")
endif()
if(EXISTS ${WORK}/prefix_configured_only/bin/spectralseg)
  fail("cmake --install without a build installed a tool it did not build")
endif()

# 3. optional dependencies: asked for QUIETly, reported as components
set(probe ${WORK}/probe)
file(WRITE ${probe}/CMakeLists.txt "cmake_minimum_required(VERSION 3.16)
project(probe LANGUAGES CXX)
string(REPLACE \",\" \";\" COMPONENTS \"\${COMPONENTS}\")
find_package(SpectralSeg REQUIRED COMPONENTS \${COMPONENTS})
get_target_property(definitions SpectralSeg::SpectralSeg INTERFACE_COMPILE_DEFINITIONS)
message(STATUS \"probe: version \${SpectralSeg_VERSION} TBB \${SpectralSeg_TBB_FOUND} Embree \${SpectralSeg_Embree_FOUND} Rendering \${SpectralSeg_Rendering_FOUND} definitions \${definitions}\")
")
set(components "")
set(expect_definitions "SPECTRALSEG_USE_MAXFLOW")
if(WITH_TBB)
  list(APPEND components TBB)
  string(APPEND expect_definitions ";SPECTRALSEG_HAS_TBB")
endif()
if(WITH_EMBREE)
  list(APPEND components Embree)
  string(APPEND expect_definitions ";SPECTRALSEG_HAS_EMBREE")
endif()
if(WITH_RENDERING)
  list(APPEND components Rendering)
endif()
set(maxflow3 "")
if(WITH_LIBMAXFLOW)
  string(APPEND expect_definitions ";SPECTRALSEG_HAS_LIBMAXFLOW")
  set(maxflow3 ";SPECTRALSEG_HAS_LIBMAXFLOW")
endif()
string(REPLACE ";" "," components_arg "${components}")
run(${CMAKE_COMMAND} -S ${probe} -B ${probe}/found -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${prefix}
    "-DCOMPONENTS=${components_arg}" ${cgal_args})
if(NOT rc EQUAL 0 OR NOT out MATCHES "probe: version ${VERSION} ")
  fail("find_package(SpectralSeg REQUIRED COMPONENTS ${components}) with them installed: ${out}")
elseif(NOT out MATCHES "definitions ${expect_definitions}\n")
  fail("SpectralSeg::SpectralSeg should define ${expect_definitions}: ${out}")
endif()
run(${CMAKE_COMMAND} -S ${probe} -B ${probe}/without -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON -DCMAKE_DISABLE_FIND_PACKAGE_embree=ON ${cgal_args})
if(NOT rc EQUAL 0 OR NOT out MATCHES "TBB FALSE Embree FALSE Rendering [A-Z]+ definitions SPECTRALSEG_USE_MAXFLOW${maxflow3}\n")
  fail("a consumer without TBB and Embree must find SpectralSeg, without them: ${out}")
endif()
run(${CMAKE_COMMAND} -S ${probe} -B ${probe}/required -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON -DCOMPONENTS=TBB ${cgal_args})
if(rc EQUAL 0)
  fail("find_package(SpectralSeg REQUIRED COMPONENTS TBB) must fail without TBB: ${out}")
endif()

# 4. the README shows the consumer project as it is
file(READ ${SOURCE_DIR}/README.md readme)
foreach(f my_app.cpp CMakeLists.txt)
  file(READ ${SOURCE_DIR}/test/install_consumer/${f} code)
  string(FIND "${readme}" "${code}" at)
  if(at LESS 0)
    fail("README.md does not show test/install_consumer/${f} as it is")
  endif()
endforeach()

# 5. the README's project, built against the installed package (a consumer
#    machine without TBB and Embree), run on a shipped mesh
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/test/install_consumer -B ${WORK}/consumer -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON -DCMAKE_DISABLE_FIND_PACKAGE_embree=ON ${cgal_args})
if(NOT rc EQUAL 0)
  fail("configure of the consumer project: ${out}")
else()
  run(${CMAKE_COMMAND} --build ${WORK}/consumer)
  if(NOT rc EQUAL 0)
    fail("build of the consumer project: ${out}")
  else()
    run(${WORK}/consumer/my_app ${DATA}/elephant.off 4 ${WORK}/elephant.ply)
    if(NOT rc EQUAL 0 OR NOT out MATCHES "SpectralSeg ${VERSION}: 4 segments" OR NOT EXISTS ${WORK}/elephant.ply)
      fail("the consumer program: ${out}")
    endif()
  endif()
endif()

if(failures GREATER 0)
  message(FATAL_ERROR "install test: ${failures} checks failed")
endif()
message("install test: all checks passed")
