# `blockcontact verify` exits 0 when every criterion holds and 1 when one fails (issue 17): one real
# run of PROBLEM, its histories evaluated again as written (--histories: exit 0), then a copy with
# one channel perturbed so that exactly one criterion fails (exit 1, that row named FAIL).
#   -DBIN=blockcontact -DPYTHON=python3 -DPERTURB=perturb_history.py -DOUT=dir -DPROBLEM=name
#   -DDATASET=/supports/... -DCOMPONENT=n -DFACTOR=x -DT0=t -DT1=t -DFAILS=regex
file(REMOVE_RECURSE "${OUT}")
function(verify expected_exit)
  execute_process(COMMAND "${BIN}" verify ${PROBLEM} --no-plots ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT rc EQUAL expected_exit)
    message(FATAL_ERROR "verify ${ARGN}: exit code ${rc}, expected ${expected_exit}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

verify(0 -o "${OUT}/run")
verify(0 -o "${OUT}/same" --histories "${OUT}/run")
file(COPY "${OUT}/run/${PROBLEM}.h5" DESTINATION "${OUT}/perturbed")
execute_process(COMMAND "${PYTHON}" "${PERTURB}" "${OUT}/perturbed/${PROBLEM}.h5" "${DATASET}" ${COMPONENT} ${FACTOR}
                ${T0} ${T1} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "perturb_history.py failed (${rc})")
endif()
verify(1 -o "${OUT}/checked" --histories "${OUT}/perturbed")
# Table rows: problem, pairing (*_on_*), criterion, ..., result.
string(REGEX MATCHALL "\n${PROBLEM} +[a-z]+_on_[a-z]+ [^\n]* FAIL[^\n]*" failed_rows "${out}")
list(LENGTH failed_rows n)
if(NOT n EQUAL 1 OR NOT failed_rows MATCHES "${FAILS}")
  message(FATAL_ERROR "expected exactly one failed row matching '${FAILS}', got ${n}: ${failed_rows}")
endif()
