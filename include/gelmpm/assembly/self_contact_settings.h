#ifndef gelmpm_assembly_self_contact_settings_h
#define gelmpm_assembly_self_contact_settings_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The subsection "Contact/Self contact": contact of the gel's boundary with itself
   * (SelfContactAssembler, doc/method.md, "Contact of the gel with itself"). Off by default; a
   * scene that leaves it off has no self-contact term in its list and does no work for it.
   *
   * Every surface point of the chosen pieces against the tangent planes of the nearest facing
   * surface points, or in 2D (plane strain and axisymmetric, 'Other face = segments') against the
   * segments of their current surface polylines (SurfaceGeometry::order_along_surface()), its
   * own segments and those less than 'Minimum arc length' away along the surface excepted,
   * frictionless, by a penalty beta_s = gamma_s G / h_u on the penetration, or by Nitsche's
   * method with the same beta_s.
   */
  struct SelfContactSettings
  {
    enum class Method
    {
      none,
      penalty,
      nitsche
    };

    Method method = Method::none;
    /** gamma_s: beta_s = gamma_s G / h_u (the penalty, or Nitsche's stabilisation). */
    double penalty = 100.;
    /** The pieces whose surface points touch each other (empty: every free piece). */
    std::vector<std::string> pieces;
    /** A point and a segment closer than this (in cells of the grid as given, 'Background
     * grid/Cells', also on a refined grid) at the start of a step are a pair. */
    double search_distance = 1.;
    /** Along the surface (initial configuration), a point and the ends of a segment closer than
     * this (in the same cells) never touch: its own segments and their neighbours. */
    double minimum_arc_length = 3.;
    /** At the start of a step, a point up to this far (in the same cells) behind a segment is its
     * pair (a penetration the penalty left); farther it is the other face of a thin body. */
    double largest_depth = 0.5;
    /** Whether parts of the material that share a displacement function's support without being
     * connected there take copies of it (PointCache::separate_faces()). */
    bool separate_faces = true;
    /** Whether a converged step through which a surface point passed the other face unseen by
     * its pairs is retaken shorter ('Retake unseen passes'); otherwise such steps are counted. */
    bool retake_unseen_passes = true;
    /** 2D: whether a point touches the tangent planes of the other face's points at the step's
     * start (as in 3D) instead of the segments of the current polylines ('Other face'). */
    bool tangent_planes = true;

    bool
    enabled() const
    {
      return method != Method::none;
    }

    /** Its entries, in the subsection "Self contact" of the entered section "Contact". */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read and check them (the section "Contact" entered). */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * What the run's log should note about valid but doubtful settings (lines ending in a
     * newline), or nothing: a Nitsche 'Penalty' below the 1000 its stabilisation needs.
     */
    std::string
    notes() const;
  };
} // namespace GelMPM

#endif
