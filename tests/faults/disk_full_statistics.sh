# A full disk at statistics.csv (/dev/full): "disk full" naming the file, exit 1.
source "$(dirname "$0")/common.sh"
mkdir results
ln -s /dev/full results/statistics.csv
"$gelmpm" "$scene" --set "Time stepping/End time=0.05" >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $((status != 1)) "exit status $status, expected 1"
grep -q "disk full while writing 'results/statistics.csv'" stderr
check $? "stderr does not say 'disk full' for statistics.csv"
finish
