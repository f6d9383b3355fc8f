#ifndef gelmpm_core_serial_blas_h
#define gelmpm_core_serial_blas_h

namespace GelMPM
{
  /**
   * @brief While alive, the BLAS runs each call on the calling thread alone (OpenBLAS's
   * openblas_set_num_threads(1), restored at the end); nothing where the BLAS is not OpenBLAS.
   *
   * The assembly calls dgemm from each of deal.II's worker threads. A threaded OpenBLAS then
   * starts its own threads inside each call, more threads than cores, which spin against the
   * workers: on this project's 2-core machine a 3D assembly of 5,832 volume points took 19.4 s
   * instead of 1.8 s (doc/three_dimensions.md). MUMPS's factorisation, called from one thread,
   * keeps the BLAS threads outside the scope.
   *
   * The functions are looked up at run time, so that any BLAS the system provides links; the
   * user's OPENBLAS_NUM_THREADS is respected outside the scope.
   */
  class SerialBlasScope
  {
  public:
    SerialBlasScope();
    ~SerialBlasScope();
    SerialBlasScope(const SerialBlasScope &) = delete;
    SerialBlasScope &
    operator=(const SerialBlasScope &) = delete;

    /** Whether the BLAS is OpenBLAS, whose thread count the scope sets. */
    static bool
    controls_threads();

    /** The BLAS's thread count now (1 where it is not OpenBLAS). */
    static int
    threads();

    /**
     * One BLAS thread for the whole run unless the environment sets the count
     * (OPENBLAS_NUM_THREADS, GOTO_NUM_THREADS, OMP_NUM_THREADS); returns whether it was set.
     * deal.II's threads already use the cores, and MUMPS's BLAS threads next to them (spinning
     * between calls) slowed the free-swelling cube twofold (doc/performance.md, "The BLAS on one
     * thread").
     */
    static bool
    use_one_thread_unless_set();

  private:
    int previous = 0;
  };
} // namespace GelMPM

#endif
