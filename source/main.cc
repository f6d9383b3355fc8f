/**
 * gelmpm: runs a hydrogel scene described by a parameter file.
 *
 *   gelmpm [--set "Section/Entry=value"]... [--check] [--resume] scene.prm
 *   gelmpm --print-parameters [scene.prm]
 *   gelmpm --help
 *
 * Exit status: 0 success, 1 the run failed, 2 bad input or a checkpoint that cannot be resumed
 * (nothing is written then), 128 + the signal (130 SIGINT, 143 SIGTERM) when a signal stopped
 * the run after a step.
 */
#include <gelmpm/simulator/command_line_main.h>

int
main(int argc, char **argv)
{
  return GelMPM::run_command_line(argc, argv);
}
