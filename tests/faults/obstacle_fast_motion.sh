# A rigid sphere that would cross a round post (0.5 wide, its top 0.01 inside the sphere's path)
# in one step of 0.8: contact is found at the ends of steps only, so that step saw no contact and
# the run ended with a force of 0. The step control now bounds an obstacle's travel per step to
# half a cell (Obstacle::largest_travel_in_cells): the steps are shortened to 0.05, the log says
# so, and the sphere presses on the post on its way across. (The scene is the test's own; the
# free-swelling scene given is not used.)
source "$(dirname "$0")/common.sh"
cat >post.prm <<'SCENE'
set Dimension = 2
subsection Output
  set Directory       = results
  set Test mode       = true
  set Write particles = false
  set Interval steps  = 0
end
subsection Background grid
  set Lower corner = 0, 0
  set Upper corner = 3, 1.6
  set Cells        = 30, 16
end
subsection Geometry
  set Level set = (x - 1.45)^2 + (y - 0.5)^2 - 0.0625
end
subsection Boundary conditions
  set Pieces = base, free
  subsection base
    set Selector     = y < 0.4
    set Displacement = fixed
  end
  subsection free
    set Selector = y >= 0.4
  end
end
subsection Contact
  set Method    = penalty
  set Obstacles = ball
  subsection ball
    set Shape  = sphere
    set Center = 1.05, 1.74
    set Radius = 1
    subsection Motion
      set Function expression = 80 * t; 0
    end
  end
end
subsection Time stepping
  set Characteristic length = 1
  set Initial step          = 0.01
  set End time              = 0.01
end
SCENE
"$gelmpm" post.prm >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $status "the run should reach its end"
grep -q "shortened from dt = 0.01 to 0.000625: the obstacle 'ball' would travel 0.8" stdout
check $? "the log does not say that the obstacle's travel shortened the step"
column() { head -n 1 results/statistics.csv | tr ',' '\n' | grep -nx "$1" | cut -d: -f1; }
# Rows (after the initial one) with contact, and the largest step.
in_contact=$(awk -F, -v c="$(column contact_points)" 'NR > 2 && $c > 0' results/statistics.csv | wc -l)
largest=$(awk -F, -v c="$(column dt)" 'NR > 2 && $c > m { m = $c } END { print m }' results/statistics.csv)
pressed=$(awk -F, -v c="$(column ball_force_y)" 'NR > 2 && $c > 0.01' results/statistics.csv | wc -l)
echo "steps in contact: $in_contact, largest step: $largest, steps with a force above 0.01: $pressed"
check $((in_contact < 3)) "the sphere should touch the post in several steps"
check $((pressed < 1)) "the sphere should press on the post"
awk -v m="$largest" 'BEGIN { exit !(m <= 0.000625 * (1 + 1e-6)) }'
check $? "a step is longer than half a cell of the sphere's travel (0.000625)"
finish
