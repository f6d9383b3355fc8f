#ifndef gelmpm_simulator_peer_input_h
#define gelmpm_simulator_peer_input_h

#include <gelmpm/io/directory_lock.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/scene/material_regions.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>
#include <gelmpm/solvers/time_stepping.h>
#include <gelmpm/stability/stability_analysis.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The input of a body-fitted peer tool (gelmpm-fem-swelling, -flat-punch, -column,
   * -bilayer): the scene file of the material point scene it is compared with, read through the
   * same sections, and the peer's own section 'FE peer'.
   *
   *   gelmpm-fem-<name> [--set "Section/Entry=value"]... [--quiet] scene.prm
   *
   * The gel ('Material' with its 'Regions'), the time stepping ('Time stepping'), Newton
   * ('Newton'), the linear solver ('Linear solver') and the stability rules ('Stability') are
   * the scene's, checked exactly as gelmpm checks them, so that a comparison of the two models
   * cannot use two different gels or step rules by mistake. What only a mesh has (cells, degree)
   * and the body and loading of the benchmark, which the peer builds on its own mesh, are
   * entries of 'FE peer' (declared by the tool), given with --set. Every other section of the
   * scene is read and checked but not used.
   */
  class PeerInput
  {
  public:
    /**
     * Read the command line @p argv of the tool @p tool: every section of a 2D scene file and
     * 'FE peer', whose entries @p declare_peer declares (inside the subsection). Throws
     * InputError (naming the entry) on bad input.
     */
    PeerInput(const int                                              argc,
              const char *const                                     *argv,
              const std::string                                     &tool,
              const std::function<void(dealii::ParameterHandler &)> &declare_peer);

    /** --help was given: print usage() and stop. */
    bool help = false;
    /** --quiet: no line per step. */
    bool quiet = false;

    /** The usage text of the tool, with the entries of 'FE peer' and their documentation. */
    std::string
    usage(const std::string &description) const;

    /** The scene's gel ('Material'). */
    FloryRehnerGel<2> material;
    /** The gels of 'Material/Regions' (the first is the section's own). */
    MaterialRegions<2> regions;
    TimeStepping       time_stepping;
    NewtonSettings     newton;
    LinearSolver       linear_solver;
    StabilitySettings  stability;

    /** Declare 'Degree' (of the displacement, Taylor-Hood) in 'FE peer': every peer has it. */
    static void
    declare_degree(dealii::ParameterHandler &prm);

    /**
     * 'Degree' of the section 'FE peer' (entered). Throws InputError above largest_degree, where
     * the cell matrices and quadrature tables, growing as k^6, run out of memory long before a
     * finer mesh of a lower degree would.
     */
    static unsigned int
    degree(const dealii::ParameterHandler &prm);

    /** The highest 'Degree' accepted. */
    static constexpr unsigned int largest_degree = 10;

    /** Declare 'Output directory' in 'FE peer', with @p default_directory and @p contents. */
    static void
    declare_output_directory(dealii::ParameterHandler &prm,
                             const std::string        &default_directory,
                             const std::string        &contents);

    /**
     * Throw InputError ('Material/Regions') if the scene has material regions: the peers whose
     * body is one gel (all but gelmpm-fem-bilayer) would drop them without a word.
     */
    void
    require_one_gel() const;

    /**
     * Claim @p directory ('FE peer/Output directory') for the tool's output as gelmpm claims its
     * own 'Output/Directory': checked by check_output_directory(), refused if it holds the
     * results of a gelmpm run (its parameters.prm, original.prm, particles.pvd or
     * checkpoint.bin: the peer's statistics.csv would replace that run's), created, and locked
     * (DirectoryLock, so that neither a gelmpm run nor another peer writes into it meanwhile).
     * Throws InputError naming the entry. The lock is held while the returned object lives.
     */
    std::unique_ptr<DirectoryLock>
    claim_output_directory(const std::string &directory) const;

    /** The parameters as read, in 'FE peer' for the tool's own entries. */
    dealii::ParameterHandler &
    peer_section();
    /** Leave 'FE peer'. */
    void
    leave_peer_section();

  private:
    std::string tool;
    /** The scene file given on the command line. */
    std::string              scene_file;
    dealii::ParameterHandler prm;
  };
} // namespace GelMPM

#endif
