#include <gelmpm/core/serial_blas.h>

#include <cstdlib>
#include <dlfcn.h>
#include <initializer_list>

namespace GelMPM
{
  namespace
  {
    using SetThreads = void (*)(int);
    using GetThreads = int (*)();

    /** OpenBLAS's thread controls, or null where another BLAS is loaded. */
    struct OpenBlasControls
    {
      SetThreads set = nullptr;
      GetThreads get = nullptr;

      OpenBlasControls()
      {
        set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
        get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
        if (set == nullptr || get == nullptr)
          set = nullptr, get = nullptr;
      }
    };

    const OpenBlasControls &
    controls()
    {
      static const OpenBlasControls found;
      return found;
    }
  } // namespace


  SerialBlasScope::SerialBlasScope()
  {
    if (!controls_threads())
      return;
    previous = controls().get();
    if (previous != 1)
      controls().set(1);
  }


  SerialBlasScope::~SerialBlasScope()
  {
    if (controls_threads() && previous != 1)
      controls().set(previous);
  }


  bool
  SerialBlasScope::controls_threads()
  {
    return controls().set != nullptr;
  }


  bool
  SerialBlasScope::use_one_thread_unless_set()
  {
    for (const char *name : {"OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS"})
      if (std::getenv(name) != nullptr)
        return false;
    if (!controls_threads())
      return false;
    controls().set(1);
    return true;
  }


  int
  SerialBlasScope::threads()
  {
    return controls_threads() ? controls().get() : 1;
  }
} // namespace GelMPM
