# A run with the gel's contact with itself ('Contact/Self contact') stopped after its first step
# (the step in which two blocks of one body first touch, tests/simulator/self_contact_blocks) and
# resumed from its checkpoint: statistics.csv and events.csv are those of the uninterrupted run bit
# for bit, and the 'self_contact' event is not written again after the resume (the state "touching
# at the last step" is in the checkpoint). (The scene is the blocks' scene; the free-swelling scene
# given is not used.)
source "$(dirname "$0")/common.sh"
blocks="$(dirname "$0")/../simulator/self_contact_blocks_scene.prm"
fail=0
"$gelmpm" "$blocks" --set "Output/Directory=uninterrupted" --set "Time stepping/End time=4e-3" \
  >uninterrupted.log 2>&1 || { echo "FAIL: the uninterrupted run failed"; fail=1; }
"$gelmpm" "$blocks" --set "Output/Directory=results" --set "Checkpoint/Interval steps=1" \
  --set "Time stepping/End time=1e-3" >first.log 2>&1 || { echo "FAIL: the first part failed"; fail=1; }
"$gelmpm" "$blocks" --resume --set "Output/Directory=results" --set "Checkpoint/Interval steps=1" \
  --set "Time stepping/End time=4e-3" >resumed.log 2>&1 || { echo "FAIL: the resumed run failed"; fail=1; }
check_statistics
cmp -s uninterrupted/statistics.csv results/statistics.csv ||
  { echo "FAIL: statistics.csv differs from the uninterrupted run's"; fail=1; }
cmp -s uninterrupted/events.csv results/events.csv ||
  { echo "FAIL: events.csv differs from the uninterrupted run's"; fail=1; }
[[ $(grep -c '^self_contact,' results/events.csv) -eq 1 ]] ||
  { echo "FAIL: events.csv has not exactly one self_contact row"; fail=1; }
finish
