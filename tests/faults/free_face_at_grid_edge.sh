# A free face of the body on the edge of the grid is not pinned there: the run stops with the
# time, the point and the fix, keeps what it wrote and exits with 1.
source "$(dirname "$0")/common.sh"
"$gelmpm" "$scene" --set "Geometry/Boxes=1, 1 : 1.5, 1.5" >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $((status != 1)) "exit status $status, expected 1"
grep -q "the run stopped: at t/tau_d = .*, the material point at .* has crossed the edge of the background grid; enlarge the grid" stderr
check $? "stderr does not name the time, the point and the fix"
grep -q "is kept in results" stderr
check $? "stderr does not say what was kept"
check_statistics
finish
