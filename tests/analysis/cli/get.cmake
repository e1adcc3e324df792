# granpen get (values of a JSON output by key path) and granpen gap-score (a gap selftest
# case scored), end to end on files written here: known answers, named errors, exit status.
set(GET_DIR ${CMAKE_CURRENT_BINARY_DIR}/get)
file(MAKE_DIRECTORY ${GET_DIR})
file(WRITE ${GET_DIR}/c.json "{\n  \"tool\": \"granpen collapse\",\n  \"peak_exponent\": 1.48003,\n  \"traces\": [\n    {\"file\": \"a b.csv\", \"v0\": 50, \"peak\": 584377},\n    {\"file\": \"c.csv\", \"v0\": 100, \"peak\": 1581410}\n  ]\n}\n")
file(WRITE ${GET_DIR}/bad.json "{\n  \"a\": 1,\n  \"b\": tru\n}\n")
set(GET $<TARGET_FILE:granpen-cli> get ${GET_DIR}/c.json)
# case | arguments (after FILE) | expected output (regex)
set(GET_CASES
  "one|peak_exponent|^1.48003\n$"
  "records|traces[*].file,traces[*].peak,tool|^a b.csv\t584377\tgranpen collapse\nc.csv\t1581410\tgranpen collapse\n$"
  "match|traces[v0=100].file|^c.csv\n$"
  "missing_default|traces[*].k_z,--missing,undefined|^undefined\nundefined\n$")
foreach(entry ${GET_CASES})
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 name)
  list(GET parts 1 args)
  list(GET parts 2 want)
  string(REPLACE "," ";" args "${args}")
  add_test(NAME cli_get_${name} COMMAND ${GET} ${args})
  set_tests_properties(cli_get_${name} PROPERTIES LABELS "unit;cli" PASS_REGULAR_EXPRESSION "${want}")
endforeach()
# named errors and their exit status (1: the file or a key; 2: usage)
add_test(NAME cli_get_missing_key COMMAND sh -c "'$<TARGET_FILE:granpen-cli>' get '${GET_DIR}/c.json' traces[2].v0; echo exit=$?")
add_test(NAME cli_get_not_json COMMAND sh -c "'$<TARGET_FILE:granpen-cli>' get '${GET_DIR}/bad.json' a; echo exit=$?")
add_test(NAME cli_get_no_file COMMAND sh -c "'$<TARGET_FILE:granpen-cli>' get '${GET_DIR}/none.json' a; echo exit=$?")
add_test(NAME cli_get_bad_path COMMAND sh -c "'$<TARGET_FILE:granpen-cli>' get '${GET_DIR}/c.json' 'traces[x]'; echo exit=$?")
add_test(NAME cli_get_no_key COMMAND sh -c "'$<TARGET_FILE:granpen-cli>' get '${GET_DIR}/c.json'; echo exit=$?")
set_tests_properties(cli_get_missing_key cli_get_not_json cli_get_no_file cli_get_bad_path cli_get_no_key PROPERTIES LABELS "unit;cli")
set_tests_properties(cli_get_missing_key PROPERTIES PASS_REGULAR_EXPRESSION
  "granpen get: error: [^ ]*/c.json: index 2 past the end of 'traces' \\(2 elements\\)\nexit=1")
set_tests_properties(cli_get_not_json PROPERTIES PASS_REGULAR_EXPRESSION "granpen get: error: [^ ]*/bad.json:3:[0-9]+: not JSON.*exit=1")
set_tests_properties(cli_get_no_file PROPERTIES PASS_REGULAR_EXPRESSION "granpen get: error: [^ ]*/none.json: cannot read it.*exit=1")
set_tests_properties(cli_get_bad_path PROPERTIES PASS_REGULAR_EXPRESSION "key path 'traces\\[x\\]': \\[x\\] is not an index.*exit=1")
set_tests_properties(cli_get_no_key PROPERTIES PASS_REGULAR_EXPRESSION "granpen get: error: .*keys.*exit=2")

# gap-score on a diagnosis of known answer: cohesion explained, G_all 0.186 -> 0.012, truth
# 1800 above its limit 411: its row, passing (exit 0); the same scored as friction: a
# confident wrong answer (exit 3)
file(WRITE ${GET_DIR}/diagnosis.json "{\"verdict\": \"explained\", \"top_effect\": \"cohesion\", \"magnitude\": 1489.39, \"gap_before\": 0.185637, \"gap_after\": 0.0118398, \"tie\": null, \"confirmation\": {\"explained_fraction\": 0.9403}, \"heldout\": {\"v0\": 50, \"gap_before\": 0.237817, \"gap_after\": 0.0355194}, \"ranking\": [{\"effect\": \"cohesion\", \"magnitude_error\": 120.602}], \"detection_limits\": [{\"effect\": \"cohesion\", \"limit\": 410.881, \"reference\": 1000, \"limit_other_side\": null}]}\n")
add_test(NAME cli_gap_score_pass COMMAND sh -c "'$<TARGET_FILE:granpen-cli>' gap-score '${GET_DIR}/diagnosis.json' --case cohesion --truth cohesion --magnitude 1800 --wall-seconds 3; echo exit=$?")
add_test(NAME cli_gap_score_wrong COMMAND sh -c "'$<TARGET_FILE:granpen-cli>' gap-score '${GET_DIR}/diagnosis.json' --case friction --truth friction --magnitude 0.1; echo exit=$?")
set_tests_properties(cli_gap_score_pass cli_gap_score_wrong PROPERTIES LABELS "unit;cli")
set_tests_properties(cli_gap_score_pass PROPERTIES PASS_REGULAR_EXPRESSION
  "^\\| cohesion \\| cohesion \\| 1800 \\| 411 \\| explained \\| cohesion \\| 1.49e\\+03 \\| 0.186 \\| 0.012 \\| 50 \\| 0.238 \\| 0.036 \\| 0.94 \\| 3 \\| yes \\|\nexit=0")
set_tests_properties(cli_gap_score_wrong PROPERTIES PASS_REGULAR_EXPRESSION
  "^\\| friction \\| friction \\| 0.1 \\| - \\| explained \\| cohesion \\| 1.49e\\+03 .*\\| - \\| \\*\\*no\\*\\* \\|\nexit=3")
