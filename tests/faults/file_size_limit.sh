# The file-size limit is lowered while the run writes statistics.csv (prlimit; the limit cannot be
# set before the start, where MPI needs large files): the row that crosses it is not left torn.
source "$(dirname "$0")/common.sh"
command -v prlimit >/dev/null || { echo "SKIP: no prlimit"; exit 0; }
# The limit holds for every file the process writes: its log goes to /dev/null, not to a file.
"$gelmpm" "$scene" >/dev/null 2>stderr &
pid=$!
for _ in $(seq 600); do
  [[ $(cat results/statistics.csv 2>/dev/null | wc -l) -ge 4 ]] && break
  sleep 0.1
done
# Stopped while the limit is set: a row written between reading the size and setting the limit
# (a loaded machine) would otherwise put the file beyond the limit before it holds.
kill -STOP $pid
size=$(stat -c %s results/statistics.csv)
prlimit --pid $pid --fsize=$((size + 500))
kill -CONT $pid
wait $pid
status=$?
echo "exit status: $status"; cat stderr
check $((status != 1)) "exit status $status, expected 1"
grep -q "'results/statistics.csv' reached the file-size limit" stderr
check $? "stderr does not name statistics.csv and the file-size limit"
check $(($(stat -c %s results/statistics.csv) > size + 500)) "statistics.csv exceeds the limit"
check_statistics
finish
