# --resume refuses, with one message, exit status 2 and nothing written: an output directory
# without a checkpoint, a checkpoint written for other parameters, by another version, a
# truncated or altered checkpoint, a statistics.csv shorter than the checkpoint counted, an End
# time before the checkpoint's time, and a .vtu file that particles.pvd listed, deleted. A later
# End time is no other scene: it continues the finished run.
source "$(dirname "$0")/common.sh"
options=(--set "Time stepping/End time=1" --set "Checkpoint/Interval steps=5")
"$gelmpm" "$scene" "${options[@]}" >run.log 2>&1
check $? "the run that writes the checkpoint failed"
[[ -s results/checkpoint.bin ]]
check $? "the run wrote no results/checkpoint.bin"
cp -r results good

# refused DESCRIPTION EXPECTED [ARGS...]: --resume must exit with 2 and one error line containing
# EXPECTED, and leave results/ as it was.
refused() {
  local what=$1 expected=$2
  shift 2
  local before
  before=$(cd results && md5sum ./*)
  "$gelmpm" "$scene" "${options[@]}" --resume "$@" >stdout 2>stderr
  local status=$?
  echo "$what: exit status $status: $(cat stderr)"
  check $((status != 2)) "$what: exit status $status, expected 2"
  grep -qF -- "$expected" stderr
  check $? "$what: stderr lacks '$expected'"
  [[ $(grep -c . stderr) -eq 1 ]]
  check $? "$what: expected exactly one error line"
  [[ $(cd results && md5sum ./*) == "$before" ]]
  check $? "$what: results/ was changed"
}

refused "other parameters" "was written for other parameters: 'Material/Shear modulus' is '1' in the checkpoint and '2' in the scene" \
  --set "Material/Shear modulus=2"

sed -i '1s/GelMPM [0-9.]*$/GelMPM 0.0.0-other/' results/checkpoint.bin
refused "other version" "was written by another GelMPM version"
cp good/checkpoint.bin results/

truncate -s $(($(stat -c %s results/checkpoint.bin) / 2)) results/checkpoint.bin
refused "truncated" "checkpoint.bin' is damaged: it has"
cp good/checkpoint.bin results/

size=$(stat -c %s results/checkpoint.bin)
printf '\x00\xff\x00\xff' | dd of=results/checkpoint.bin bs=1 seek=$((size / 2)) conv=notrunc status=none
refused "altered" "checkpoint.bin' is damaged: its contents do not match the checksum"
cp good/checkpoint.bin results/

head -c $(($(stat -c %s good/statistics.csv) / 2)) good/statistics.csv >results/statistics.csv
refused "statistics.csv cut short" "needs 'results/statistics.csv' as it was then"
cp good/statistics.csv results/

refused "End time before the checkpoint" "'Time stepping/End time' is 0.5, before the time of the checkpoint" \
  --set "Time stepping/End time=0.5"

rows=$(wc -l <results/statistics.csv)
"$gelmpm" "$scene" "${options[@]}" --resume --set "Time stepping/End time=1.5" >stdout 2>stderr
check $? "a later End time: the resumed run failed: $(cat stderr)"
[[ $(wc -l <results/statistics.csv) -gt $rows ]]
check $? "a later End time: the resumed run added no rows"
cp good/statistics.csv good/checkpoint.bin results/

rm results/checkpoint.bin
refused "no checkpoint" "found no checkpoint in 'results'"

rm -rf results
particles=(--set "Output/Write particles=true" --set "Output/Interval steps=5")
"$gelmpm" "$scene" "${options[@]}" "${particles[@]}" >run.log 2>&1
check $? "the run that writes particles and a checkpoint failed"
rm results/particles-00001.vtu
refused "a .vtu that particles.pvd listed, deleted" \
  "needs 'results/particles-00001.vtu' as it was then" "${particles[@]}"
finish
