# blockcontact generate / verify (docs/verification.md). Included by tests/cli/CMakeLists.txt.
add_test(NAME cli.generate.all COMMAND blockcontact generate --all -o ${CMAKE_CURRENT_BINARY_DIR}/sslide)
set_tests_properties(cli.generate.all PROPERTIES PASS_REGULAR_EXPRESSION "sslide1k.k: .*sslide12l_vec.k: ")
add_test(NAME cli.generate.list COMMAND blockcontact generate --list)
set_tests_properties(cli.generate.list PROPERTIES PASS_REGULAR_EXPRESSION "sslide9ps +Type 9")
add_test(NAME cli.generate.unknown COMMAND blockcontact generate sslide4 -o ${CMAKE_CURRENT_BINARY_DIR}/sslide)
set_tests_properties(cli.generate.unknown PROPERTIES WILL_FAIL TRUE)
add_test(NAME cli.verify.help COMMAND blockcontact verify --help)
set_tests_properties(cli.verify.help PROPERTIES PASS_REGULAR_EXPRESSION "--spec")
add_test(NAME cli.verify.unknown COMMAND blockcontact verify sslide4 -o ${CMAKE_CURRENT_BINARY_DIR}/verify)
set_tests_properties(cli.verify.unknown PROPERTIES WILL_FAIL TRUE)
# The whole pipeline without contact (runs, HDF5/CSV, criteria, report; no plots): the
# interface criteria fail, so only the output is checked.
add_test(NAME cli.verify.pipeline COMMAND blockcontact verify sslide9pt --drop-contacts --no-plots
  -o ${CMAKE_CURRENT_BINARY_DIR}/verify_pipeline)
set_tests_properties(cli.verify.pipeline PROPERTIES
  PASS_REGULAR_EXPRESSION "sslide9pt +[0-9.]+ s +FAIL +ran [0-9]+ cycles.*separated: min rel y t>0.15.*report: ")
# The same with the plots (python3-matplotlib, python3-h5py from scripts/setup.sh).
add_test(NAME cli.verify.plots COMMAND blockcontact verify sslide7k --drop-contacts
  -o ${CMAKE_CURRENT_BINARY_DIR}/verify_plots --plot-script ${PROJECT_SOURCE_DIR}/scripts/plot_sslide.py)
set_tests_properties(cli.verify.plots PROPERTIES PASS_REGULAR_EXPRESSION "plot_sslide: 1 problem\\(s\\) plotted")
set_tests_properties(cli.generate.all cli.generate.list cli.generate.unknown cli.verify.help cli.verify.unknown
  cli.verify.pipeline cli.verify.plots PROPERTIES LABELS "unit;cli")

# Exit codes (issue 17): 0 when every criterion of a real run holds, 1 when a perturbed copy of its
# histories fails one (the bottom support's R_y 5% high over [0.2, 0.3]: only "mean R_y" fails).
if(EXISTS /usr/bin/python3)
  set(VERIFY_PYTHON /usr/bin/python3)
else()
  set(VERIFY_PYTHON python3)
endif()
add_test(NAME cli.verify.exit_code COMMAND ${CMAKE_COMMAND} -DBIN=$<TARGET_FILE:blockcontact>
  -DPYTHON=${VERIFY_PYTHON} -DPERTURB=${CMAKE_CURRENT_SOURCE_DIR}/perturb_history.py
  -DOUT=${CMAKE_CURRENT_BINARY_DIR}/verify_exit_code -DPROBLEM=sslide2kc
  -DDATASET=/supports/solid_on_solid_bottom/reaction -DCOMPONENT=1 -DFACTOR=1.05 -DT0=0.2 -DT1=0.3
  "-DFAILS=solid_on_solid +mean R_y \\[0.2,0.3\\]"
  -P ${CMAKE_CURRENT_SOURCE_DIR}/verify_exit_code.cmake)
set_tests_properties(cli.verify.exit_code PROPERTIES LABELS "unit;cli")
