# An output directory with the sticky bit (as /tmp) that holds an earlier run's files of another
# user: the run can neither remove nor replace them, and stopped at its first write (exit status 1,
# "cannot write 'results/statistics.csv'"). It is bad input: exit status 2, one message naming
# 'Output/Directory', nothing written. Run as root, the test runs gelmpm as the user nobody (root
# may replace any file); as another user it skips.
source "$(dirname "$0")/common.sh"
if [[ $(id -u) -ne 0 ]] || ! command -v setpriv >/dev/null; then
  echo "SKIP: needs root and setpriv to run as another user"; finish
fi
chmod 755 "$work"
mkdir -p results && chmod 1777 results
touch results/statistics.csv results/parameters.prm
cp "$scene" scene.prm && chmod 644 scene.prm
setpriv --reuid=65534 --regid=65534 --clear-groups "$gelmpm" scene.prm >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $((status != 2)) "exit status $status, expected 2"
grep -q "'Output/Directory' is 'results', which holds '.*' of another user, and its sticky bit lets only that user remove or replace it" stderr
check $? "stderr does not name 'Output/Directory' and the file"
check $(($(grep -c . stderr) != 1)) "one message"
check $(($(ls results | wc -l) != 2)) "nothing written into results"
finish
