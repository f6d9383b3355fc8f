// gelmpm-reference: what to expect from a scene, printed. For each gel of the scene file (the
// section 'Material' and each of its regions) the closed-form references of the Flory-Rehner law
// at the scene's initial and bath chemical potentials: the free-swelling stretch and J, the
// drained and undrained moduli, the consolidation coefficient and its time scale, the swelling
// of a film bonded on a rigid substrate against the creasing threshold, and for two gels
// Timoshenko's curvature of the bilayer (doc/reference_values.md).
//
//   gelmpm-reference [--set "Section/Entry=value"]... [--csv] [--bath mu]
//                    [--thicknesses h_1,h_2] scene.prm
//
// The values come from the gel law the solver assembles (FloryRehnerGel, through GelReferences).
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/material/gel_references.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/scene/material_regions.h>
#include <gelmpm/simulator/scene_structure.h>
#include <gelmpm/simulator/simulator.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <exception>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace GelMPM;

  const std::string tool = "gelmpm-reference";

  /** The creasing threshold of a neo-Hookean surface in plane strain (Hong, Zhao & Suo 2009). */
  constexpr double crease_stretch_ratio = 2.4;
  /** Biot's linear surface instability of a neo-Hookean half-space (1/0.544^2). */
  constexpr double biot_stretch_ratio = 3.38;


  struct Options
  {
    bool                  help = false;
    bool                  csv  = false;
    std::optional<double> bath;
    std::optional<double> ramp;
    std::vector<double>   thicknesses;
    GelMPM::CommandLine   command_line;
  };


  std::string
  usage()
  {
    return "Usage: " + tool +
           " [--set \"Section/Entry=value\"]... [--csv] [--bath mu] [--ramp T] [--thicknesses h_1,h_2] "
           "scene.prm\n\n"
           "Prints, for each gel of the scene ('Material' and its regions), the closed-form\n"
           "references of the Flory-Rehner law at the scene's initial chemical potential mu_0\n"
           "and its bath mu_b: free swelling, drained and undrained moduli, the consolidation\n"
           "coefficient, a film bonded on a rigid substrate against the creasing threshold, and\n"
           "with two gels Timoshenko's curvature of the bilayer. Stresses in the unit of\n"
           "'Material/Shear modulus', mu in k_BT, lengths in the scene's, times in tau_d.\n\n"
           "  --set \"Section/Entry=value\"  override an entry of the scene file, as for gelmpm\n"
           "  --bath mu        the bath's mu/k_BT (default: the prescribed chemical potential of\n"
           "                   the scene's boundary pieces at 'Time stepping/End time')\n"
           "  --ramp T         also print a bath ramped in stretch over T tau_d, ready to paste:\n"
           "                   the free-swelling stretch of 'Material' linear in time from mu_0's\n"
           "                   to mu_b's (doc/own_scenes.md section 11; T about L^2/c)\n"
           "  --thicknesses h_1,h_2\n"
           "                   the initial thicknesses of the two layers of a bilayer, 'Material'\n"
           "                   first, then its region (for Timoshenko's curvature)\n"
           "  --csv            one line per value: region,quantity,mu_over_kT,value,formula\n"
           "  --help           this text\n\n"
           "Exit status: 0, or 2 on bad input (one line naming the entry or option).\n";
  }


  double
  parse_number(const std::string &text, const std::string &option)
  {
    std::size_t end   = 0;
    double      value = 0.;
    try
      {
        value = std::stod(text, &end);
      }
    catch (const std::exception &)
      {
        end = 0;
      }
    require(end > 0 && end == text.size() && std::isfinite(value),
            option,
            "is '" + text + "', not a number",
            "give a number, e.g. " + option + " 0.1");
    return value;
  }


  std::vector<double>
  parse_thicknesses(const std::string &text)
  {
    std::vector<double> values;
    std::stringstream   stream(text);
    std::string         item;
    while (std::getline(stream, item, ','))
      values.push_back(parse_number(item, "--thicknesses"));
    require(values.size() == 2 && values[0] > 0. && values[1] > 0.,
            "--thicknesses",
            "is '" + text + "', but takes two positive thicknesses",
            "give the two layers' initial thicknesses, 'Material' first: --thicknesses 0.1,0.1");
    return values;
  }


  /** The tool's own options, the rest (--set, the scene file) read as gelmpm reads them. */
  Options
  parse_options(const int argc, const char *const *argv)
  {
    Options                   options;
    std::vector<const char *> rest = {argv[0]};
    for (int i = 1; i < argc; ++i)
      {
        const std::string argument = argv[i];
        const auto        value    = [&]() {
          require(i + 1 < argc, argument, "is missing its value", "see '" + tool + " --help'");
          return std::string(argv[++i]);
        };
        if (argument == "--csv")
          options.csv = true;
        else if (argument == "--bath")
          options.bath = parse_number(value(), "--bath");
        else if (argument == "--ramp")
          {
            options.ramp = parse_number(value(), "--ramp");
            require(*options.ramp > 0.,
                    "--ramp",
                    "is not positive, but takes the ramp's duration",
                    "give the ramp's duration in tau_d, e.g. --ramp 100");
          }
        else if (argument == "--thicknesses")
          options.thicknesses = parse_thicknesses(value());
        else if (argument == "--check" || argument == "--resume" ||
                 argument == "--print-parameters")
          throw InputError("",
                           "'" + argument + "' is an option of gelmpm, not of " + tool,
                           "see '" + tool + " --help'");
        else
          rest.push_back(argv[i]);
      }
    require(!(options.csv && options.ramp),
            "--ramp",
            "prints a bath expression, which has no place in --csv",
            "give --ramp without --csv");
    options.command_line = CommandLine::parse(rest.size(), rest.data());
    options.help         = options.command_line.help;
    return options;
  }


  /** One value of the output: a quantity of a region, at a chemical potential or at none. */
  struct Row
  {
    std::string           quantity;
    std::string           label;
    std::optional<double> at_initial, at_bath;
    std::string           formula;
    /** The value belongs to a chemical potential (not a constant such as a threshold). */
    bool per_state = true;
  };


  /** The bath's mu and where it comes from. */
  struct Bath
  {
    double      mu;
    std::string source;
  };


  std::string
  number(const double x, const int digits = 7)
  {
    std::ostringstream text;
    text << std::setprecision(digits) << x;
    return text.str();
  }


  /**
   * The bath: --bath, or the prescribed chemical potential of the boundary pieces at the end of
   * the run, which must be one value (sampled at the grid's corners and centre).
   */
  template <int dim>
  Bath
  bath_of(BoundaryConditions<dim>     &pieces,
          const std::optional<double> &given,
          const double                 end_time,
          const dealii::Point<dim>    &lower,
          const dealii::Point<dim>    &upper,
          const double                 mu_0)
  {
    if (given)
      return {*given, "--bath"};
    std::vector<std::pair<std::string, double>> values;
    const std::vector<dealii::Point<dim>>       samples = {lower, upper, 0.5 * (lower + upper)};
    for (unsigned int i = 0; i < pieces.n_pieces(); ++i)
      {
        auto &piece = pieces.piece(i);
        if (!piece.chemical_potential_prescribed())
          continue;
        piece.set_time(end_time);
        for (const auto &x : samples)
          values.emplace_back(piece.name, piece.chemical_potential_value().value(x));
      }
    if (values.empty())
      return {mu_0, "no piece prescribes mu: the initial mu_0"};
    for (const auto &[name, mu] : values)
      require(std::abs(mu - values.front().second) <= 1e-12 * (1. + std::abs(mu)),
              "Boundary conditions/" + name + "/Chemical potential value",
              "is " + number(mu) + " at 'Time stepping/End time' = " + number(end_time) +
                ", and piece '" + values.front().first + "' prescribes " +
                number(values.front().second) + ": the scene has no one bath",
              "give the bath's mu with --bath");
    // + 0. turns a bath of -0 (mu_0 times a ramp's zero) into 0.
    return {values.front().second + 0.,
            "piece '" + values.front().first + "' at End time = " + number(end_time)};
  }


  std::string
  kinematics_name(const SwellingKinematics kinematics)
  {
    return kinematics == SwellingKinematics::three_dimensional ? "3D" : "plane strain";
  }


  /** Free swelling at mu_0 and mu_b in @p kinematics. */
  void
  add_free_swelling(std::vector<Row>        &rows,
                    const GelReferences     &gel,
                    const double             mu_0,
                    const double             mu_b,
                    const SwellingKinematics kinematics,
                    const std::string       &suffix)
  {
    const auto  initial = gel.free_swelling(mu_0, kinematics);
    std::string what    = kinematics == SwellingKinematics::three_dimensional
                            ? "P = 0 at F = lambda I: eq. (22)"
                            : "P_11 = P_22 = 0 at F = diag(lambda; lambda; lambda_0)";
    // The 3D rows of a plane-strain scene: its bath may lie between the largest mu of 3D swelling
    // and the larger one of plane strain (1.7e-3 and 5.7e-3 for Table 1).
    std::optional<SwollenState> bath;
    const double                largest = gel.gel().largest_swelling_chemical_potential();
    if (kinematics == SwellingKinematics::plane_strain || mu_b <= largest)
      bath = gel.free_swelling(mu_b, kinematics);
    else
      what += "; none at mu_b > " + number(largest, 4) + ", where it swells without bound";
    const std::string name = kinematics_name(kinematics);
    rows.push_back({"lambda_free_" + suffix,
                    "free swelling " + name + ": lambda from dry",
                    initial.stretch_from_dry,
                    bath ? std::optional<double>(bath->stretch_from_dry) : std::nullopt,
                    what});
    rows.push_back({"stretch_free_" + suffix,
                    "free swelling " + name + ": lambda / lambda_0",
                    initial.stretch_from_initial,
                    bath ? std::optional<double>(bath->stretch_from_initial) : std::nullopt,
                    "the size from the initial state"});
    rows.push_back(
      {"J_free_" + suffix,
       "free swelling " + name + ": J",
       initial.J,
       bath ? std::optional<double>(bath->J) : std::nullopt,
       kinematics == SwellingKinematics::three_dimensional ? "lambda^3" : "lambda_0 lambda^2"});
  }


  void
  add_moduli(std::vector<Row>        &rows,
             const GelReferences     &gel,
             const double             mu_0,
             const double             mu_b,
             const SwellingKinematics kinematics,
             const double             diffusivity_unit)
  {
    const auto a   = gel.drained_moduli(mu_0, kinematics);
    const auto b   = gel.drained_moduli(mu_b, kinematics);
    const auto row = [&](const std::string &quantity,
                         const std::string &label,
                         const double       x,
                         const double       y,
                         const std::string &formula) {
      rows.push_back({quantity, label, x, y, formula});
    };
    const std::string about = "about free swelling (" + kinematics_name(kinematics) + ")";
    row("G_drained",
        "drained shear modulus G_s",
        a.shear_modulus,
        b.shear_modulus,
        "c_1212 of the tangent " + about + " = G lambda_x^2 / J");
    row("nu_drained",
        "drained Poisson ratio nu",
        a.poisson_ratio,
        b.poisson_ratio,
        "lambda_L / (2 (lambda_L + G_s)); lambda_L = c_1122 = J psi'' + psi'");
    row("E_drained",
        "drained Young's modulus E",
        a.young_modulus,
        b.young_modulus,
        "2 G_s (1 + nu)");
    if (kinematics == SwellingKinematics::plane_strain)
      row("E_plane_strain_drained",
          "drained plane-strain modulus E'",
          a.plane_strain_modulus,
          b.plane_strain_modulus,
          "E / (1 - nu^2) = 4 G_s (lambda_L + G_s) / (lambda_L + 2 G_s)");
    else
      row("E_biaxial_drained",
          "drained biaxial modulus",
          a.biaxial_modulus,
          b.biaxial_modulus,
          "E / (1 - nu)");
    row("G_undrained",
        "undrained shear modulus",
        a.shear_modulus,
        b.shear_modulus,
        "G_s: shear changes no volume");
    row("nu_undrained",
        "undrained Poisson ratio",
        0.5,
        0.5,
        "1/2: no solvent moves; polymer and solvent incompressible");
    if (kinematics == SwellingKinematics::plane_strain)
      row("E_plane_strain_undrained",
          "undrained plane-strain modulus",
          4. * a.shear_modulus,
          4. * b.shear_modulus,
          "4 G_s");
    else
      row("E_undrained",
          "undrained Young's modulus",
          3. * a.shear_modulus,
          3. * b.shear_modulus,
          "3 G_s");
    row("permeability",
        "permeability kappa",
        a.permeability,
        b.permeability,
        "D N nu (J - 1) / J / G: q = -kappa grad p; p = (k_BT/nu) mu");
    row("c_over_D",
        "consolidation coefficient c / D",
        a.consolidation_coefficient / diffusivity_unit,
        b.consolidation_coefficient / diffusivity_unit,
        "kappa (lambda_L + 2 G_s) = 2 (1 - nu) / (1 - 2 nu) G_s kappa (D: 'Material/Diffusivity')");
    row("tau_c_over_tau_d",
        "L^2 / c in tau_d",
        diffusivity_unit / a.consolidation_coefficient,
        diffusivity_unit / b.consolidation_coefficient,
        "D / c; L = 'Time stepping/Characteristic length'; for a length H: (H/L)^2 D / c");
  }


  void
  add_film(std::vector<Row> &rows, const GelReferences &gel, const double mu_0, const double mu_b)
  {
    const auto initial = gel.constrained_swelling(mu_0);
    const auto bath    = gel.constrained_swelling(mu_b);
    rows.push_back({"s_film",
                    "bonded film: s = h/H = lambda_y/lambda_x",
                    initial.stretch_from_initial,
                    bath.stretch_from_initial,
                    "P_22 = 0 at F = diag(lambda_0; lambda_0 s; lambda_0) (uniaxial swelling)"});
    rows.push_back({"lambda_film_from_dry",
                    "bonded film: thickness stretch from dry",
                    initial.stretch_from_dry,
                    bath.stretch_from_dry,
                    "lambda_0 s"});
    rows.push_back({"J_film", "bonded film: J", initial.J, bath.J, "lambda_0^3 s"});
    rows.push_back({"s_crease",
                    "creasing threshold s_c",
                    std::nullopt,
                    crease_stretch_ratio,
                    "lambda_y/lambda_x = 2.4 (Hong, Zhao & Suo 2009; neo-Hookean; plane strain)",
                    false});
    rows.push_back({"mu_at_s_crease",
                    "bath mu at which s = s_c",
                    std::nullopt,
                    gel.constrained_swelling_chemical_potential(crease_stretch_ratio),
                    "P_22 = 0 solved for mu at s = 2.4 (> 0: beyond a bath of pure solvent)",
                    false});
    rows.push_back({"s_biot",
                    "Biot's surface instability s_B",
                    std::nullopt,
                    biot_stretch_ratio,
                    "1 / 0.544^2 (linear; wrinkles)",
                    false});
    rows.push_back({"mu_at_s_biot",
                    "bath mu at which s = s_B",
                    std::nullopt,
                    gel.constrained_swelling_chemical_potential(biot_stretch_ratio),
                    "P_22 = 0 solved for mu at s = 3.38 (> 0: beyond a bath of pure solvent)",
                    false});
  }


  /** Timoshenko's curvature of the two gels as layers, 'Material' first. */
  std::vector<Row>
  bilayer_rows(const GelReferences       &layer_1,
               const GelReferences       &layer_2,
               const double               mu_b,
               const SwellingKinematics   kinematics,
               const std::vector<double> &thicknesses)
  {
    const double     a_1          = layer_1.free_swelling(mu_b, kinematics).stretch_from_initial;
    const double     a_2          = layer_2.free_swelling(mu_b, kinematics).stretch_from_initial;
    const auto       m_1          = layer_1.drained_moduli(mu_b, kinematics);
    const auto       m_2          = layer_2.drained_moduli(mu_b, kinematics);
    const bool       plane_strain = kinematics == SwellingKinematics::plane_strain;
    const double     E_1          = plane_strain ? m_1.plane_strain_modulus : m_1.biaxial_modulus;
    const double     E_2          = plane_strain ? m_2.plane_strain_modulus : m_2.biaxial_modulus;
    const double     mismatch     = a_1 / a_2 - 1.;
    std::vector<Row> rows         = {
              {"bilayer_mismatch",
               "mismatch strain eps",
               std::nullopt,
               mismatch,
               "a_1 / a_2 - 1; a_k: layer k's free-swelling stretch from the initial state (" +
                 kinematics_name(kinematics) + ")"},
              {"bilayer_modulus_ratio",
               "modulus ratio n = E_1/E_2",
               std::nullopt,
               E_1 / E_2,
               std::string(plane_strain ? "plane-strain" : "biaxial") + " drained moduli at mu_b"}};
    if (thicknesses.empty())
      return rows;
    const double h_1 = thicknesses[0] * a_1, h_2 = thicknesses[1] * a_2;
    rows.push_back({"bilayer_thickness_1",
                    "swollen thickness h_1",
                    std::nullopt,
                    h_1,
                    "h_1 (--thicknesses) a_1"});
    rows.push_back({"bilayer_thickness_2",
                    "swollen thickness h_2",
                    std::nullopt,
                    h_2,
                    "h_2 (--thicknesses) a_2"});
    rows.push_back({"bilayer_curvature",
                    "Timoshenko's curvature kappa",
                    std::nullopt,
                    timoshenko_curvature(mismatch, h_1, h_2, E_1, E_2),
                    "6 eps (1+m)^2 / (h [3 (1+m)^2 + (1+mn)(m^2 + 1/(mn))]); m = h_1/h_2; "
                    "h = h_1 + h_2; > 0: towards layer 2"});
    return rows;
  }


  void
  print_table(std::ostream           &out,
              const std::string      &title,
              const std::vector<Row> &rows,
              const double            mu_0,
              const double            mu_b)
  {
    out << "\n" << title << "\n";
    out << "  " << std::left << std::setw(46) << "quantity" << std::right << std::setw(14)
        << ("mu_0 = " + number(mu_0, 5)) << std::setw(14) << ("mu_b = " + number(mu_b, 5))
        << "  formula\n";
    for (const auto &row : rows)
      {
        out << "  " << std::left << std::setw(46) << row.label << std::right;
        for (const auto &value : {row.at_initial, row.at_bath})
          out << std::setw(14) << (value ? number(*value) : std::string("-"));
        out << "  " << row.formula << "\n";
      }
  }


  void
  print_csv(std::ostream           &out,
            const std::string      &region,
            const std::vector<Row> &rows,
            const double            mu_0,
            const double            mu_b)
  {
    for (const auto &row : rows)
      {
        if (row.at_initial)
          out << region << ',' << row.quantity << ',' << number(mu_0, 10) << ','
              << number(*row.at_initial, 10) << ",\"" << row.formula << "\"\n";
        if (row.at_bath)
          out << region << ',' << row.quantity << ','
              << (row.per_state ? number(mu_b, 10) : std::string()) << ','
              << number(*row.at_bath, 10) << ",\"" << row.formula << "\"\n";
      }
  }


  /**
   * The bath mu_b(t) whose free-swelling stretch from dry S(t) = l0 + (leq - l0) min(t/T, 1) goes
   * linearly from the initial state to the bath's: mu = N nu (S^2 - 1)/J + ln(1 - 1/J) + 1/J +
   * chi/J^2 (J = S^3, or lambda_0 S^2 in plane strain: P_11 = 0), clamped at mu_b against the
   * rounding of leq. As 'Function constants' and 'Function expression' of a piece.
   */
  void
  print_ramp(std::ostream            &out,
             const GelReferences     &gel,
             const double             mu_0,
             const double             mu_b,
             const SwellingKinematics kinematics,
             const double             duration)
  {
    const auto       &law = gel.gel();
    const std::string S   = "(l0 + (leq - l0) * min(t / T, 1))";
    const std::string J =
      kinematics == SwellingKinematics::plane_strain ? "(l0 * " + S + "^2)" : "(" + S + "^3)";
    out << "\nBath ramped in stretch over T = " << number(duration)
        << " tau_d (doc/own_scenes.md section 11), 'Material' " << kinematics_name(kinematics)
        << ": for the 'Chemical potential value' of the pieces\n"
        << "    set Function constants  = l0=" << number(law.lambda_0(), 12)
        << ", leq=" << number(gel.free_swelling(mu_b, kinematics).stretch_from_dry, 12)
        << ", nv=" << number(law.N_nu(), 12) << ", chi=" << number(law.chi(), 12)
        << ", mub=" << number(mu_b, 12) << ", T=" << number(duration, 12) << "\n"
        << "    set Function expression = " << (mu_b >= mu_0 ? "min" : "max") << "(nv * (" << S
        << "^2 - 1) / " << J << " + log(1 - 1 / " << J << ") + 1 / " << J << " + chi / " << J
        << "^2, mub)\n";
  }


  template <int dim>
  int
  run(const Options &options, const SceneStructure &structure)
  {
    const auto              &cl = options.command_line;
    dealii::ParameterHandler prm;
    Simulator<dim>::declare_parameters(prm, structure);
    read_scene_file(prm, cl.scene_file, cl.overrides);
    FloryRehnerGel<dim> material;
    material.parse_parameters(prm);
    MaterialRegions<dim> regions;
    regions.parse_parameters(prm, structure.material_regions, material);
    BoundaryConditions<dim> pieces;
    pieces.parse_parameters(prm, structure.boundary_pieces);
    prm.enter_subsection("Time stepping");
    const double end_time = prm.get_double("End time");
    const double length   = prm.get_double("Characteristic length");
    prm.leave_subsection();
    prm.enter_subsection("Background grid");
    const auto lower_corner =
      get_double_list(prm, "Lower corner", "Background grid/Lower corner", dim);
    const auto upper_corner =
      get_double_list(prm, "Upper corner", "Background grid/Upper corner", dim);
    const bool axisymmetric = prm.get("Coordinate system") == "axisymmetric";
    prm.leave_subsection();
    dealii::Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = lower_corner[d];
        upper[d] = upper_corner[d];
      }

    const double mu_0    = material.mu_0();
    const Bath   bath    = bath_of(pieces, options.bath, end_time, lower, upper, mu_0);
    const double largest = regions.largest_swelling_chemical_potential(axisymmetric);
    require(bath.mu <= largest,
            options.bath ? "--bath" : "Boundary conditions",
            "gives the bath mu_b = " + number(bath.mu) + ", above " + number(largest) +
              ", the largest mu at which every gel of the scene has a swollen equilibrium",
            "give a bath at or below " + number(largest));
    require(options.thicknesses.empty() || regions.size() == 2,
            "--thicknesses",
            "gives two layers, but the scene has " + std::to_string(regions.size()) + " gel(s)",
            "give a scene with one region besides 'Material' (e.g. prm/bilayer_actuator.prm)");

    const SwellingKinematics kinematics = (dim == 3 || axisymmetric)
                                            ? SwellingKinematics::three_dimensional
                                            : SwellingKinematics::plane_strain;
    const std::string        scene_kind = dim == 3 ? "3D"
                                          : axisymmetric
                                            ? "axisymmetric: the body of revolution swells in 3D"
                                            : "2D: plane strain, F_33 = lambda_0";
    const double             D          = material.diffusivity();
    std::ostream            &out        = std::cout;
    if (options.csv)
      out << "region,quantity,mu_over_kT,value,formula\n";
    else
      out << tool << ": " << cl.scene_file << " (" << scene_kind << "), " << regions.size()
          << (regions.size() == 1 ? " gel" : " gels") << "\n"
          << "Units: stresses in those of 'Material/Shear modulus', mu in k_BT, lengths in the "
             "scene's, times in tau_d = L^2/D (L = "
          << number(length) << ", D = " << number(D) << ").\n"
          << "Initial mu_0 = " << number(mu_0, 8)
          << " ('Material/Initial state'); bath mu_b = " << number(bath.mu, 8) << " ("
          << bath.source << ").\n";

    std::vector<GelReferences> gels;
    for (unsigned int r = 0; r < regions.size(); ++r)
      gels.emplace_back(regions[r]);
    for (unsigned int r = 0; r < regions.size(); ++r)
      {
        const auto      &gel = regions[r];
        std::vector<Row> rows;
        rows.push_back(
          {"lambda_0",
           "initial stretch lambda_0 (eq. (22) at mu_0)",
           gels[r].free_swelling(mu_0, SwellingKinematics::three_dimensional).stretch_from_dry,
           std::nullopt,
           "P = 0 at F = lambda_0 I and mu_0 (TOMS 748)"});
        rows.push_back(
          {"mu_0",
           "initial mu_0 (eq. (22) at lambda_0)",
           gels[r].free_swelling_chemical_potential(gel.lambda_0(),
                                                    SwellingKinematics::three_dimensional),
           std::nullopt,
           "N nu (1/l - 1/l^3) + ln(1 - 1/l^3) + 1/l^3 + chi/l^6"});
        add_free_swelling(rows,
                          gels[r],
                          mu_0,
                          bath.mu,
                          kinematics,
                          kinematics == SwellingKinematics::plane_strain ? "plane_strain" : "3d");
        if (kinematics == SwellingKinematics::plane_strain)
          add_free_swelling(rows,
                            gels[r],
                            mu_0,
                            bath.mu,
                            SwellingKinematics::three_dimensional,
                            "3d");
        add_moduli(rows, gels[r], mu_0, bath.mu, kinematics, D);
        add_film(rows, gels[r], mu_0, bath.mu);
        const std::string region = regions.name(r);
        if (options.csv)
          print_csv(out, region, rows, mu_0, bath.mu);
        else
          print_table(out,
                      "Gel '" + region + "': G = " + number(gel.shear_modulus()) +
                        ", chi = " + number(gel.chi()) + ", N nu = " + number(gel.N_nu()) +
                        ", D = " + number(gel.diffusivity()) +
                        ", lambda_0 = " + number(gel.lambda_0()),
                      rows,
                      mu_0,
                      bath.mu);
      }
    if (regions.size() == 2)
      {
        const auto rows = bilayer_rows(gels[0], gels[1], bath.mu, kinematics, options.thicknesses);
        if (options.csv)
          print_csv(out, "bilayer", rows, mu_0, bath.mu);
        else
          {
            print_table(out,
                        "Bilayer: layer 1 '" + regions.name(0) + "', layer 2 '" + regions.name(1) +
                          "', drained at mu_b",
                        rows,
                        mu_0,
                        bath.mu);
            if (options.thicknesses.empty())
              out << "  (give the layers' initial thicknesses, --thicknesses h_1,h_2, for "
                     "Timoshenko's curvature)\n";
          }
      }
    if (options.ramp)
      print_ramp(out, gels[0], mu_0, bath.mu, kinematics, *options.ramp);
    return 0;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const Options options = parse_options(argc, argv);
      if (options.help)
        {
          std::cout << usage();
          return 0;
        }
      const auto structure =
        SceneStructure::read(options.command_line.scene_file, options.command_line.overrides);
      return structure.dimension == 2 ? run<2>(options, structure) : run<3>(options, structure);
    }
  catch (const InputError &e)
    {
      std::cerr << tool << ": " << e.what() << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << tool << ": " << e.what() << std::endl;
      return 1;
    }
}
