# The Blender add-on, headless: zips blender/spectralseg_blender as a user
# would install it, writes the tool's labels of a mesh (k = 4 and --k auto),
# and runs test_addon.py in Blender, which installs the zip, segments the
# same mesh with the add-on and compares. Invoked by CTest with
# -DBLENDER=... -DSPECTRALSEG=... -DMODULE_DIR=... -DSOURCE=... -DMESH=... -DWORK=...
# [-DRENDER=OUT.png]
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/scripts)
execute_process(COMMAND ${CMAKE_COMMAND} -E tar cf ${WORK}/spectralseg_blender.zip --format=zip
                        spectralseg_blender/__init__.py
                WORKING_DIRECTORY ${SOURCE}/blender RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not zip the add-on")
endif()
set(expect "")
if(NOT DEFINED RENDER)
  foreach(k 4 auto)
    execute_process(COMMAND ${SPECTRALSEG} segment ${MESH} --k ${k} --labels ${WORK}/tool_${k}.seg -q
                    RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "spectralseg segment --k ${k} failed")
    endif()
  endforeach()
  set(expect --expect-k 4 ${WORK}/tool_4.seg --expect-auto ${WORK}/tool_auto.seg)
else()
  set(expect --auto --render ${RENDER})
endif()
# the add-on goes into a scripts folder of its own, not the user's
execute_process(COMMAND ${CMAKE_COMMAND} -E env BLENDER_USER_SCRIPTS=${WORK}/scripts
                        ${BLENDER} -b --factory-startup --python-exit-code 1
                        --python ${SOURCE}/test/blender/test_addon.py --
                        --addon ${WORK}/spectralseg_blender.zip --module-dir ${MODULE_DIR} --mesh ${MESH} ${expect}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
string(REGEX REPLACE "Fra:[^\n]*\n" "" out "${out}") # Cycles' progress lines
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the Blender add-on test failed (exit code ${rc})")
endif()
