#!/usr/bin/env bash
# run_case.sh TEST PROGRAM CASE COMPARISON NUMDIFF SCRIPTS PERL: one case of a test program
# (tests/cmake/gelmpm_pickup_cases.cmake), run and compared in the current directory by deal.II's
# own stages: run_test.sh run (PROGRAM CASE's stdout and stderr into 'output'; a non-zero exit
# status fails), normalize.pl, run_test.sh diff (numdiff against COMPARISON).
set -u
test_name="$1" program="$2" case_name="$3" comparison="$4" numdiff="$5" scripts="$6" perl="$7"
sh "${scripts}/run_test.sh" run "${test_name}" "${program}" "${case_name}" || exit 1
"${perl}" -pi "${scripts}/normalize.pl" output || exit 1
sh "${scripts}/run_test.sh" diff "${test_name}" "${numdiff}" "${comparison}" || exit 1
echo "${test_name}: PASSED."
