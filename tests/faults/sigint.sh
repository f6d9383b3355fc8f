# SIGINT (Ctrl-C) in the middle of a run: the run ends after the current step with a complete last
# output, says so and exits with 130.
source "$(dirname "$0")/common.sh"
check_signal INT 130
finish
