#include <gelmpm/core/unit_tables.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  namespace UnitTables
  {
    /**
     * Every entry of a scene with its physical dimension: the one table of the conversion.
     * An entry that is not here is refused in a laboratory scene unless it is at its default
     * (tests/units checks that every declared entry is here).
     */
    const std::vector<EntryRule> &
    entry_rules()
    {
      using Q                                   = Quantity;
      static const std::vector<EntryRule> rules = {
        {"Dimension", Q::none},
        {"Background grid/Cells", Q::none},
        {"Background grid/Coordinate system", Q::none},
        {"Background grid/Lower corner", Q::length},
        {"Background grid/Upper corner", Q::length},
        {"Background grid/Refinement boxes", Q::length},
        {"Background grid/Refinement band", Q::length},
        {"Background grid/Refinement band pieces", Q::none},
        {"Background grid/Refinement obstacle band", Q::length},
        {"Background grid/Refinement moving region", Q::none, Form::moving_level_set},
        {"Background grid/Refinement obstacles", Q::none},
        {"Background grid/Refinement mu range", Q::chemical_potential},
        {"Background grid/Refinement mu gradient jump", Q::chemical_potential},
        {"Background grid/Refinement material region", Q::none, Form::level_set},
        {"Background grid/Refinement levels", Q::none},
        {"Background grid/Refinement budget", Q::none},
        {"Background grid/Refinement grading", Q::none},
        {"Background grid/Refinement region", Q::none, Form::level_set},
        {"Boundary conditions/Pieces", Q::none},
        {"Boundary conditions/*/Chemical potential", Q::none},
        {"Boundary conditions/*/Displacement", Q::none},
        {"Boundary conditions/*/Selector", Q::none, Form::selector},
        {"Boundary conditions/*/Selector constants", Q::constants},
        {"Boundary conditions/*/Chemical potential value/Function expression",
         Q::chemical_potential,
         Form::function},
        {"Boundary conditions/*/Displacement value/Function expression", Q::length, Form::function},
        {"Boundary conditions/*/Flux/Function expression", Q::velocity, Form::function},
        {"Boundary conditions/*/Traction/Function expression", Q::stress, Form::function},
        {"Boundary conditions/*/*/Function constants", Q::constants},
        {"Boundary conditions/*/*/Variable names", Q::none},
        {"Checkpoint/Interval minutes", Q::none}, // wall-clock minutes
        {"Checkpoint/Interval steps", Q::none},
        {"Contact/Active set factor", Q::none},
        {"Contact/Grid sides", Q::none},
        {"Contact/Method", Q::none},
        {"Contact/Obstacles", Q::none},
        {"Contact/Penalty", Q::none},
        {"Contact/Self contact/Largest depth", Q::none}, // in cells
        {"Contact/Self contact/Separate faces", Q::none},
        {"Contact/Self contact/Retake unseen passes", Q::none},
        {"Contact/Self contact/Other face", Q::none},
        {"Contact/Self contact/Method", Q::none},
        {"Contact/Self contact/Minimum arc length", Q::none}, // in cells
        {"Contact/Self contact/Penalty", Q::none},
        {"Contact/Self contact/Pieces", Q::none},
        {"Contact/Self contact/Search distance", Q::none}, // in cells
        {"Contact/*/Center", Q::length},
        {"Contact/*/Edge radius", Q::length},
        {"Contact/*/Normal", Q::none},
        {"Contact/*/Permeable", Q::none},
        {"Contact/*/Radius", Q::length},
        {"Contact/*/Shape", Q::none},
        {"Contact/*/Motion/Function expression", Q::length, Form::function},
        {"Contact/*/Motion/Function constants", Q::constants},
        {"Contact/*/Motion/Variable names", Q::none},
        {"Discretisation/Chemical potential degree", Q::none},
        {"Discretisation/Chemical potential grid", Q::none},
        {"Discretisation/Displacement degree", Q::none},
        {"Discretisation/Extended B-splines", Q::none},
        {"Geometry/Boxes", Q::length},
        {"Geometry/Holes", Q::length, Form::holes},
        {"Geometry/Level set", Q::none, Form::level_set},
        {"Geometry/Level set constants", Q::constants},
        {"Geometry/Mesh file", Q::refused},
        {"Linear solver/Automatic memory share", Q::none},
        {"Linear solver/Compression", Q::none},
        {"Linear solver/Displacement preconditioner", Q::none},
        {"Linear solver/Krylov iterations", Q::none},
        {"Linear solver/Krylov restart", Q::none},
        {"Linear solver/Krylov tolerance", Q::none},
        {"Linear solver/LSC block threshold", Q::none},
        {"Linear solver/Multigrid coarse size", Q::none},
        {"Linear solver/Multigrid cycle", Q::none},
        {"Linear solver/Multigrid smoother", Q::none},
        {"Linear solver/Multigrid smoothing steps", Q::none},
        {"Linear solver/Ordering", Q::none},
        {"Linear solver/Precision", Q::none},
        {"Linear solver/Schur complement", Q::none},
        {"Linear solver/Solver", Q::none},
        {"Material/Diffusivity", Q::diffusivity},
        {"Material/Flory-Huggins chi", Q::none},
        {"Material/Initial chemical potential", Q::chemical_potential},
        {"Material/Initial state", Q::none},
        {"Material/Initial stretch", Q::none},
        {"Material/N nu", Q::none},
        {"Material/Regions", Q::none},
        {"Material/Shear modulus", Q::stress},
        {"Material/*/Diffusivity", Q::diffusivity},
        {"Material/*/Flory-Huggins chi", Q::none},
        {"Material/*/Mesh group", Q::none},
        {"Material/*/N nu", Q::none},
        {"Material/*/Selector", Q::none, Form::selector},
        {"Material/*/Shear modulus", Q::stress},
        {"Material points/Points per cell", Q::none},
        {"Material points/Surface points per cell edge", Q::none},
        {"Newton/Initial chemical potential", Q::none},
        {"Newton/Initial displacement", Q::none},
        {"Newton/Line search", Q::none},
        {"Newton/Log failures", Q::none},
        {"Newton/Maximum iterations", Q::none},
        {"Newton/Maximum reuses", Q::none},
        {"Newton/Freeze switches after", Q::none},
        {"Newton/Reuse contraction", Q::none},
        {"Newton/Reuse step ratio", Q::none},
        {"Newton/Smallest damping", Q::none},
        {"Newton/Tolerance", Q::none},
        {"Nitsche/Chemical potential penalty", Q::none},
        {"Nitsche/Displacement penalty", Q::none},
        {"Nitsche/Variant", Q::none},
        {"Observables/Boundary condition error", Q::none},
        {"Observables/Centre offset pieces", Q::none},
        {"Observables/Chemical potential oscillation", Q::none},
        {"Observables/Crease angle", Q::none},
        {"Observables/Crease skewness", Q::none},
        {"Observables/Fold approach distance", Q::none}, // in cells
        {"Observables/Fold arc length", Q::none},        // in cells
        {"Observables/Forces and fluxes", Q::none},
        {"Observables/Instability threshold", Q::none},
        {"Observables/Pore centres", Q::length},
        {"Observables/Pore piece", Q::none},
        {"Observables/Radius centre", Q::length},
        {"Observables/Radius piece", Q::none},
        {"Observables/Shape pieces", Q::none},
        {"Observables/Surface pieces", Q::none},
        {"Observables/Thickness direction", Q::none},
        {"Observables/Thickness pieces", Q::none},
        {"Observables/Volume ratio range", Q::none},
        {"Output/Directory", Q::none},
        {"Output/Interval steps", Q::none},
        {"Output/Interval time", Q::time},
        {"Output/Test mode", Q::none},
        {"Output/Write grid", Q::none},
        {"Output/Write particles", Q::none},
        {"Stability/Bisection tolerance", Q::time},
        {"Stability/Condition number", Q::none},
        {"Stability/Drained eigenvalues", Q::none},
        {"Stability/Eigensolver", Q::none},
        {"Stability/End at onset", Q::none},
        {"Stability/Inertia", Q::none},
        {"Stability/Inf-sup constant", Q::none},
        {"Stability/Onset criterion", Q::none},
        {"Stability/Perturbation amplitude", Q::length},
        {"Stability/Perturbation direction", Q::none},
        {"Stability/Schur eigenvalues", Q::none},
        {"Stability/Signature from", Q::none},
        {"Stability/Signature step control", Q::none},
        {"Stability/Step while unstable", Q::time},
        {"Stability/Write mode", Q::none},
        {"Time stepping/Characteristic length", Q::length},
        {"Time stepping/Cut factor", Q::none},
        {"Time stepping/Displacement tolerance", Q::length},
        {"Time stepping/End at equilibrium", Q::rate},
        {"Time stepping/End time", Q::time},
        {"Time stepping/Error norm", Q::none},
        {"Time stepping/Growth below iterations", Q::none},
        {"Time stepping/Growth factor", Q::none},
        {"Time stepping/Initial step", Q::time},
        {"Time stepping/Largest increment", Q::none}, // in cells
        {"Time stepping/Maximum steps", Q::none},
        {"Time stepping/Minimum step", Q::time},
        {"Time stepping/Step caps", Q::time},
        {"Time stepping/Stop at times", Q::time},
        {"Time stepping/Tolerance", Q::none}, // per unit relative time, in L and k_BT
        {"Time stepping/Tolerance until", Q::time},
        {"Units/*", Q::none}};
      return rules;
    }


    Column
    column_kind(const std::string              &column,
                const std::vector<std::string> &pieces,
                const std::vector<std::string> &obstacles)
    {
      static const std::map<std::string, Column> exact = {
        {"step", Column::dimensionless},
        {"time", Column::scene_time},
        {"t_over_tau_d", Column::tau_d},
        {"dt", Column::step},
        {"newton_iterations", Column::dimensionless},
        {"attempts", Column::dimensionless},
        {"residual_u", Column::dimensionless},
        {"residual_mu", Column::dimensionless},
        {"n_dofs_u", Column::dimensionless},
        {"n_dofs_mu", Column::dimensionless},
        {"n_active_cells", Column::dimensionless},
        {"n_particles", Column::dimensionless},
        {"n_pos", Column::dimensionless},
        {"n_neg", Column::dimensionless},
        {"n_zero", Column::dimensionless},
        {"n_neg_uu", Column::dimensionless},
        {"centre_offset_x", Column::length},
        {"centre_offset_y", Column::length},
        {"centre_offset_z", Column::length},
        {"centre_distance", Column::length},
        {"delta_h_over_h0", Column::dimensionless},
        {"radius_over_R0", Column::dimensionless},
        {"J_min", Column::dimensionless},
        {"J_mean", Column::dimensionless},
        {"J_max", Column::dimensionless},
        {"mu_oscillation", Column::dimensionless},
        {"u_bc_error", Column::length},
        {"mu_bc_error", Column::chemical_potential},
        {"inf_sup", Column::dimensionless},
        {"condition_number", Column::dimensionless},
        {"mu_boundary", Column::chemical_potential},
        {"solvent_volume", Column::volume},
        {"solvent_imbalance", Column::dimensionless},
        {"wall_time", Column::wall},
        {"contact_points", Column::dimensionless},
        {"contact_penetration", Column::length},
        {"self_contact_points", Column::dimensionless},
        {"self_contact_force", Column::force},
        {"self_contact_area", Column::area},
        {"self_contact_penetration", Column::length}};
      if (const auto found = exact.find(column); found != exact.end())
        return found->second;
      const auto numbered = [&](const std::string &prefix) {
        return column.rfind(prefix, 0) == 0 &&
               column.find_first_not_of("0123456789", prefix.size()) == std::string::npos &&
               column.size() > prefix.size();
      };
      for (const char *prefix :
           {"pore_ratio_", "pore_curvature_", "pore_creases_", "pore_contact_"})
        if (numbered(prefix))
          return Column::dimensionless;
      if (numbered("pore_turning_"))
        return Column::degrees;
      static const std::map<std::string, Column> piece_columns = {
        {"relief", Column::length},
        {"curvature", Column::dimensionless}, // times h_u
        {"turning", Column::degrees},
        {"folds", Column::dimensionless},
        {"force_x", Column::force},
        {"force_y", Column::force},
        {"force_z", Column::force},
        {"inflow", Column::volume_rate},
        {"solvent_in", Column::volume},
        {"fit_curvature", Column::inverse_length},
        {"fit_residual", Column::length},
        {"amplitude", Column::length},
        {"skewness", Column::dimensionless},
        {"wavelength", Column::length},
        {"relative_amplitude", Column::dimensionless},
        {"dip_crest_ratio", Column::dimensionless}};
      static const std::map<std::string, Column> obstacle_columns = {{"force_x", Column::force},
                                                                     {"force_y", Column::force},
                                                                     {"force_z", Column::force},
                                                                     {"contact_area", Column::area},
                                                                     {"contact_radius",
                                                                      Column::length}};
      for (const auto &[names, table] :
           {std::make_pair(&obstacles, &obstacle_columns), std::make_pair(&pieces, &piece_columns)})
        for (const auto &name : *names)
          if (column.rfind(name + "_", 0) == 0)
            if (const auto found = table->find(column.substr(name.size() + 1));
                found != table->end())
              return found->second;
      return Column::unknown;
    }
  } // namespace UnitTables
} // namespace GelMPM
