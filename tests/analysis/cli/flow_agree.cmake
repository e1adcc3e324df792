# granpen flow against compute flow/azimuthal on every sampled timestep of the deck
# (cmake -P): for each block of the compute's file, `granpen flow DUMP --steps T` and
# lammps_agree flow; then that it rejects a wrong frame.
# -DCLI= -DAGREE= -DDUMP= -DTRACE= -DCOMPUTE= -DOUT=
file(STRINGS "${COMPUTE}" heads REGEX "^[0-9]+ [0-9]+$")
list(LENGTH heads n)
if(n LESS 3)
  message(FATAL_ERROR "${COMPUTE}: ${n} blocks, at least 3 expected")
endif()
foreach(h ${heads})
  string(REGEX REPLACE " .*" "" step "${h}")
  execute_process(COMMAND ${CLI} flow ${DUMP} --trace ${TRACE} --steps ${step} --stress cmp_stress
                    --dg 0.4 --rho 3.0 --out ${OUT}/${step}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "granpen flow --steps ${step}: exit ${rc}\n${out}\n${err}")
  endif()
  execute_process(COMMAND ${AGREE} flow ${COMPUTE} ${step} ${OUT}/${step}/flow_fields.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  message("${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "timestep ${step}: granpen flow and compute flow/azimuthal differ")
  endif()
endforeach()
# the check can fail: both sides call the same kernels (src/flow_bins.h), so what it tests
# is the two data paths (in-run against from-dump); the fields of the first frame against
# the compute's last block (a frame picked wrongly) must differ
list(GET heads 0 first)
list(GET heads -1 last)
string(REGEX REPLACE " .*" "" first "${first}")
string(REGEX REPLACE " .*" "" last "${last}")
execute_process(COMMAND ${AGREE} flow ${COMPUTE} ${last} ${OUT}/${first}/flow_fields.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(rc EQUAL 0 OR NOT out MATCHES "DIFFER")
  message(FATAL_ERROR "lammps_agree accepts the fields of timestep ${first} as the compute's of ${last}:\n${out}")
endif()
message("granpen flow agrees with compute flow/azimuthal on ${n} timesteps (and lammps_agree "
        "rejects timestep ${first}'s fields as ${last}'s)")
