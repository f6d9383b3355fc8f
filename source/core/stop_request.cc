#include <gelmpm/core/stop_request.h>

#include <csignal>

namespace GelMPM
{
  namespace
  {
    // The one piece of global state: a signal handler can only set a flag.
    volatile std::sig_atomic_t received = 0;

    extern "C" void
    request_stop(const int signal)
    {
      received = signal;
      std::signal(signal, SIG_DFL);
    }
  } // namespace


  void
  install_stop_handlers()
  {
    std::signal(SIGTERM, request_stop);
    std::signal(SIGINT, request_stop);
    std::signal(SIGXFSZ, SIG_IGN);
  }


  int
  stop_signal()
  {
    return received;
  }


  const char *
  signal_name(const int signal)
  {
    switch (signal)
      {
        case SIGTERM:
          return "SIGTERM";
        case SIGINT:
          return "SIGINT";
        default:
          return "a signal";
      }
  }
} // namespace GelMPM
