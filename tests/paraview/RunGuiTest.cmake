# The ParaView GUI test: paraview plays GuiTest.xml back after GuiSetup.py
# and compares its render view with the baseline. paraview writes the image
# it made over the baseline path, so the committed baseline is copied first.
#   cmake -DPARAVIEW=... -DSOURCE=tests/paraview -DWORK=dir -P RunGuiTest.cmake
file(MAKE_DIRECTORY "${WORK}")
file(COPY_FILE "${SOURCE}/GuiTest.png" "${WORK}/baseline.png")
execute_process(
  COMMAND "${PARAVIEW}" --dr "--script=${SOURCE}/GuiSetup.py" "--test-script=${SOURCE}/GuiTest.xml"
    "--test-directory=${WORK}" "--test-baseline=${WORK}/baseline.png" --test-threshold=10 --exit
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)
message("${output}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "paraview GUI test failed (exit ${result}): plugin not loaded, a widget of "
    "GuiTest.xml not found, or the image differs from the baseline")
endif()
