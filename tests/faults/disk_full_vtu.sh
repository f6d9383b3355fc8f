# A full disk while writing a .vtu (its temporary file is /dev/full): "disk full" naming the file,
# exit 1, the .pvd lists only the complete files before it, statistics.csv has no torn row.
source "$(dirname "$0")/common.sh"
mkdir results
ln -s /dev/full results/particles-00002.vtu.tmp
"$gelmpm" "$scene" --set "Time stepping/End time=0.05" --set "Output/Write particles=true" \
  --set "Output/Interval steps=1" >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $((status != 1)) "exit status $status, expected 1"
grep -q "disk full while writing 'results/particles-00002.vtu'" stderr
check $? "stderr does not say 'disk full' for particles-00002.vtu"
check $(($(grep -c . stderr) != 1)) "expected one line on stderr"
rm -f results/particles-00002.vtu.tmp # the symbolic link is removed by the failed write already
check_statistics
check_series
check $(($(grep -c 'file=' results/particles.pvd) != 2)) "the .pvd should list the two files written"
finish
