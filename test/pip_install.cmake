# `pip install --no-build-isolation .` from the checkout into a virtual
# environment with the system's site packages (numpy, setuptools), then
# `import spectralseg` from another folder: the module must come from the
# environment, not from the build tree. Invoked by CTest with
# -DPYTHON=... -DSOURCE=... -DBUILD=... -DWORK=... -DDATA=...
# The pip build reuses this CMake build (SPECTRALSEG_BUILD_DIR: only the
# module's target, already up to date), so the test costs seconds; a pip
# install without it configures build-pip/ and compiles the module there.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/elsewhere)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
run(${PYTHON} -m venv --system-site-packages ${WORK}/venv)
run(${CMAKE_COMMAND} -E env SPECTRALSEG_BUILD_DIR=${BUILD} PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1
    ${WORK}/venv/bin/python -m pip install --no-build-isolation --no-deps ${SOURCE})
message("${out}")
execute_process(COMMAND ${WORK}/venv/bin/python -B -c
  "import spectralseg, sys, os; v, f = spectralseg.read_mesh(sys.argv[1]); l = spectralseg.k_way_segmentation(v, f, 4); print(spectralseg.__file__); print(spectralseg.__version__); print('segments', len(set(l.tolist())))"
  ${DATA}/elephant.off
  WORKING_DIRECTORY ${WORK}/elsewhere RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "import spectralseg failed in the environment")
endif()
if(NOT out MATCHES "^${WORK}/venv/lib/[^\n]*spectralseg[^\n]*\\.so\n")
  message(FATAL_ERROR "the module was not imported from the environment's site packages")
endif()
if(NOT out MATCHES "segments 4\n")
  message(FATAL_ERROR "the installed module did not segment the elephant into 4 parts")
endif()
run(${WORK}/venv/bin/python -m pip uninstall -y spectralseg)
message("pip install, import from another folder, uninstall: ok")
