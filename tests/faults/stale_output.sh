# A second, shorter run in the same directory removes the files of the first (only the names
# gelmpm writes): no particles-*.vtu that its .pvd does not list is left, and other files stay.
source "$(dirname "$0")/common.sh"
run() {
  "$gelmpm" "$scene" --set "Output/Write particles=true" --set "Output/Interval steps=1" \
    --set "Time stepping/End time=$1" >stdout 2>stderr
}
run 0.05
n_first=$(ls results/particles-*.vtu | wc -l)
touch results/notes.txt
run 0.01
n_second=$(ls results/particles-*.vtu | wc -l)
n_listed=$(grep -c 'file=' results/particles.pvd)
echo "first run: $n_first files, second run: $n_second files, $n_listed listed"
check $((n_second >= n_first)) "the second run should write fewer files than the first"
check $((n_second != n_listed)) "files of the first run are left: $(ls results)"
[[ -f results/notes.txt ]]
check $? "a file gelmpm did not write was removed"
check_series
finish
