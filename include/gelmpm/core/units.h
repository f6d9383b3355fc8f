#ifndef gelmpm_core_units_h
#define gelmpm_core_units_h

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The section `Units`: a scene written, and its statistics read, in a laboratory's
   * units, while the run itself stays normalised.
   *
   * The normalised units are the paper's: lengths by `Time stepping/Characteristic length` L,
   * times by tau_d = L^2/D (D = `Material/Diffusivity`), stresses by `Material/Shear modulus`
   * G, chemical potentials by k_BT. With `Scene values = laboratory` the scene's L, D and G are
   * laboratory values, and they are the scales: every entry of known physical dimension (the
   * table in units.cc, the only place that knows them) is divided by its scale right after the
   * scene file and the `--set` overrides are read, before anything else reads the parameters.
   * The section then says `Scene values = normalised` with the scales filled in, so that
   * parameters.prm is a normalised scene that runs the same and reads its outputs in the same
   * laboratory units.
   *
   * Function expressions stay in laboratory units: their variables are replaced by the
   * laboratory values of the normalised ones (x by (x*L), t by (t*tau_d)) and their value is
   * divided by its scale, so constants and numbers inside them keep their laboratory meaning.
   *
   * With unit names given (laboratory, or normalised with the scales), the run's statistics
   * are also written in those units to statistics_units.csv (write_statistics()).
   */
  class Units
  {
  public:
    /** Declare the section `Units` in @p prm. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Read the section `Units` of @p prm and, with `Scene values = laboratory`, convert every
     * entry of known dimension to normalised units in place. Throws InputError (naming the entry
     * and the fix) on an unknown unit name, a scale that is zero or negative, a solvent whose
     * R T / v_m disagrees with the scene's G/(N nu), an entry of unknown dimension that differs
     * from its default, or a mesh file (whose coordinates cannot be converted).
     */
    static Units
    convert_scene(dealii::ParameterHandler &prm);

    /** Whether unit names are given, so that statistics_units.csv is written. */
    bool
    enabled() const;

    /** Whether the scene was given in laboratory units and converted. */
    bool
    converted() const;

    /**
     * The table of the conversion, one line per converted entry, "entry: laboratory value ->
     * normalised value", after a header naming the scales; nothing for a normalised scene
     * without units.
     */
    void
    print_conversions(std::ostream &out) const;

    /**
     * Write @p directory/statistics_units.csv from @p directory/statistics.csv: each column in
     * the laboratory unit its header names in brackets (e.g. 'time [s]', 'top_force_y [N/mm]'),
     * columns of no dimension as they are ('[1]'), columns whose dimension is not known
     * unchanged and marked '[normalised]'. Written under a temporary name and renamed. Does
     * nothing when there is no statistics.csv.
     */
    void
    write_statistics(const std::string &directory) const;

    /**
     * @p listing (the scene reference, print_parameters_with_patterns()) with a line
     * '# Laboratory units: ...' after each entry's pattern that says how `Scene values =
     * laboratory` converts the entry (or that it does not, or that the table does not know it).
     */
    static std::string
    annotate_reference(const std::string &listing);

    /**
     * The header of statistics_units.csv's column for the statistics.csv column @p column and
     * the factor that converts its values (NaN for a column left unchanged).
     */
    std::pair<std::string, double>
    column_unit(const std::string &column) const;

  private:
    /** One converted entry, for the table. */
    struct Conversion
    {
      std::string entry;
      std::string laboratory;
      std::string normalised;
      std::string unit;
    };

    bool        laboratory = false;
    bool        units      = false;
    std::string length_unit, time_unit, stress_unit, force_unit, mu_unit;
    /** Laboratory values of one normalised length, of tau_d and of one normalised stress. */
    double length = 1., time = 1., stress = 1.;
    /** The laboratory value of k_BT in the chemical potential unit (1 for kT). */
    double mu = 1.;
    /** The laboratory value of one unit of statistics.csv's 'time': tau_d D/L^2 (normalised). */
    double scene_time = 1.;
    /** The unit of stress times (length unit)^2 in the force unit (0: no force unit). */
    double force_factor = 0.;
    /** Dimension of volumes and of a force's area: 3, or 2 in plane strain (per thickness). */
    unsigned int             measure_dim = 3;
    std::vector<std::string> pieces, obstacles;
    std::vector<Conversion>  conversions;
    std::vector<std::string> scale_notes;
  };
} // namespace GelMPM

#endif
