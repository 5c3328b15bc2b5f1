# A ParaView GUI test: paraview plays an XML test script back after
# GuiSetup.py and compares its render view with a baseline. paraview writes
# the image it made over the baseline path, so the committed baseline is
# copied first.
#   cmake -DPARAVIEW=... -DSOURCE=tests/paraview -DWORK=dir
#         [-DNAME=GuiTest] [-DBASELINE=GuiTest.png] [-DSTATE_EXPECT=regex]
#         -P RunGuiTest.cmake
# NAME.xml (or NAME.xml.in, configured with @WORK@) is played back. With
# STATE_EXPECT the playback saves the state to WORK/state.pvsm and the test
# requires that file to match the regular expression: what the panel set
# is what the representation holds.
if(NOT NAME)
  set(NAME GuiTest)
endif()
if(NOT BASELINE)
  set(BASELINE ${NAME}.png)
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(COPY_FILE "${SOURCE}/${BASELINE}" "${WORK}/baseline.png")
set(script "${SOURCE}/${NAME}.xml")
if(EXISTS "${SOURCE}/${NAME}.xml.in")
  set(script "${WORK}/${NAME}.xml")
  configure_file("${SOURCE}/${NAME}.xml.in" "${script}" @ONLY)
endif()
execute_process(
  COMMAND "${PARAVIEW}" --dr "--script=${SOURCE}/GuiSetup.py" "--test-script=${script}"
    "--test-directory=${WORK}" "--test-baseline=${WORK}/baseline.png" --test-threshold=10 --exit
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)
message("${output}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "paraview GUI test ${NAME} failed (exit ${result}): plugin not loaded, a "
    "widget of ${NAME}.xml not found, or the image differs from the baseline ${BASELINE}")
endif()
if(STATE_EXPECT)
  if(NOT EXISTS "${WORK}/state.pvsm")
    message(FATAL_ERROR "${NAME}: the playback saved no state to ${WORK}/state.pvsm")
  endif()
  file(READ "${WORK}/state.pvsm" state)
  if(NOT state MATCHES "${STATE_EXPECT}")
    message(FATAL_ERROR "${NAME}: the saved state does not match '${STATE_EXPECT}'")
  endif()
endif()
