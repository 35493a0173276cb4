# Installs the build tree into a scratch prefix, then configures, builds and runs examples/
# against it with find_package(slideline), and (WITH_CLI) runs the installed blockcontact from the
# install tree: `--help` and a `check` of tests/data/decks/unit_cube.k, with no LD_LIBRARY_PATH,
# so that the program must find libslideline through its install RPATH. Fails on any error.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring examples against the installed package failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build -j2 RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building examples failed: ${rc}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/loaded_block RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(rc)
  message(FATAL_ERROR "examples/loaded_block failed: ${rc}")
endif()

if(WITH_CLI)
  set(cli ${WORK_DIR}/prefix/${INSTALL_BINDIR}/blockcontact)
  if(NOT EXISTS ${cli})
    message(FATAL_ERROR "blockcontact was not installed to ${cli}")
  endif()
  # verify: DYNA3D's figures are compiled into the installed library (no file to find).
  foreach(args "--help" "verify;sslide7k;--no-plots;-o;${WORK_DIR}/verify"
               "check;${SOURCE_DIR}/tests/data/decks/unit_cube.k")  # check last: its "ok" is tested below
    execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH ${cli} ${args}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message(STATUS "installed blockcontact ${args}:\n${out}${err}")
    if(rc)
      message(FATAL_ERROR "installed blockcontact ${args} failed (${rc}): ${err}")
    endif()
  endforeach()
  if(NOT out MATCHES "ok")
    message(FATAL_ERROR "installed blockcontact check did not report ok")
  endif()
endif()
