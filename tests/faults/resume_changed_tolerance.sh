# --resume takes a changed 'Time stepping/Tolerance' (an entry that chooses the steps ahead, not
# the state): a run to t = 2 with Tolerance = 1e-2 is resumed with 1e-5 to t = 8. The log names the
# change, and the resumed run steps with the new tolerance: from the same checkpoint it takes many
# more steps than the continuation with 1e-2 (measured: 160 against 2). The resumed
# parameters.prm holds the new value, and a third resume with it again is no change. A changed
# 'Initial step' (which only the first step reads) is still refused.
source "$(dirname "$0")/common.sh"
options=(--set "Time stepping/Step caps=" --set "Time stepping/Growth factor=2"
  --set "Checkpoint/Interval steps=1000")
"$gelmpm" "$scene" "${options[@]}" --set "Time stepping/Tolerance=1e-2" \
  --set "Time stepping/End time=2" >first.log 2>&1
check $? "the run that writes the checkpoint failed"
cp -r results same

# steps_after DIRECTORY: the rows of DIRECTORY/statistics.csv after t = 2.
steps_after() { awk -F, 'NR > 1 && $3 > 2.0000001' "$1/statistics.csv" | wc -l; }

mv results changed && mv same results
"$gelmpm" "$scene" "${options[@]}" --set "Time stepping/Tolerance=1e-2" \
  --set "Time stepping/End time=8" --resume >same.log 2>&1
check $? "the continuation with the same tolerance failed: $(tail -n 3 same.log)"
! grep -q "changed since the checkpoint: 'Time stepping/Tolerance'" same.log
check $? "the continuation with the same tolerance says it changed"
same=$(steps_after results)
mv results same && mv changed results

"$gelmpm" "$scene" "${options[@]}" --set "Time stepping/Tolerance=1e-5" \
  --set "Time stepping/End time=8" --resume >changed.log 2>&1
check $? "the resumed run with Tolerance = 1e-5 failed: $(tail -n 3 changed.log)"
grep -qF "changed since the checkpoint: 'Time stepping/Tolerance' is '1e-5' (was '1e-2')" changed.log
check $? "the log does not name the changed tolerance"
grep -qF "changed since the checkpoint: 'Time stepping/End time' is '8' (was '2')" changed.log
check $? "the log does not name the changed End time"
changed=$(steps_after results)
echo "steps from t = 2 to 8: $same with Tolerance = 1e-2, $changed resumed with 1e-5"
[[ $same -ge 1 && $changed -ge $((10 * same)) ]]
check $? "the resumed run did not step with the new tolerance ($changed steps against $same)"
grep -q "Tolerance *= 1e-5" results/parameters.prm
check $? "parameters.prm does not hold the new tolerance"
check_statistics

"$gelmpm" "$scene" "${options[@]}" --set "Time stepping/Tolerance=1e-5" \
  --set "Time stepping/End time=9" --resume >again.log 2>&1
check $? "the second resume with Tolerance = 1e-5 failed: $(tail -n 3 again.log)"
! grep -q "changed since the checkpoint: 'Time stepping/Tolerance'" again.log
check $? "the second resume says the tolerance changed again"

"$gelmpm" "$scene" "${options[@]}" --set "Time stepping/Tolerance=1e-5" \
  --set "Time stepping/End time=10" --set "Time stepping/Initial step=1e-2" --resume \
  >stdout 2>stderr
status=$?
check $((status != 2)) "a changed Initial step: exit status $status, expected 2"
grep -qF "'Time stepping/Initial step' is '1e-3' in the checkpoint and '1e-2' in the scene" stderr
check $? "a changed Initial step: stderr lacks the refusal: $(cat stderr)"
finish
