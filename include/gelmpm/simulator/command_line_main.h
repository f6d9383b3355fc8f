#ifndef gelmpm_simulator_command_line_main_h
#define gelmpm_simulator_command_line_main_h

namespace GelMPM
{
  /**
   * Everything the gelmpm executable does (source/main.cc is this call): initialises MPI, reads
   * the command line (CommandLine), reads, checks and runs the scene, and reports an error once.
   *
   *   gelmpm [--set "Section/Entry=value"]... [--check] [--resume] scene.prm
   *   gelmpm --print-parameters [scene.prm]
   *   gelmpm --help
   *
   * Returns the exit status: 0 success, 1 the run failed, 2 bad input or a checkpoint that cannot
   * be resumed (nothing is written then), 128 + the signal (130 SIGINT, 143 SIGTERM) when a
   * signal stopped the run after a step. A function rather than main() itself so that the tests
   * of bad input (tests/input_errors) can run it in forked copies of one loaded program: starting
   * a program linked with deal.II costs about 0.4 s of symbol resolution, more than most bad
   * input takes to be found.
   */
  int
  run_command_line(int argc, char **argv);
} // namespace GelMPM

#endif
