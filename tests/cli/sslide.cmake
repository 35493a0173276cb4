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
set_tests_properties(cli.generate.all cli.generate.list cli.generate.unknown cli.verify.help cli.verify.unknown
  PROPERTIES LABELS "unit;cli")
