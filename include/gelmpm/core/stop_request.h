#ifndef gelmpm_core_stop_request_h
#define gelmpm_core_stop_request_h

namespace GelMPM
{
  /**
   * Catch SIGTERM and SIGINT: instead of ending the process, they ask the run to stop after the
   * current step (stop_signal()), so that its last output is complete. A second signal of the
   * same kind ends the process at once. SIGXFSZ is ignored, so that writing past the file-size
   * limit fails with an error the output code reports instead of killing the process.
   */
  void
  install_stop_handlers();

  /** The signal that asked the run to stop (SIGTERM, SIGINT), or 0. */
  int
  stop_signal();

  /** The name of a signal returned by stop_signal(), e.g. "SIGTERM". */
  const char *
  signal_name(const int signal);
} // namespace GelMPM

#endif
