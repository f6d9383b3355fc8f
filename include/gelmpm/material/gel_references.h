#ifndef gelmpm_material_gel_references_h
#define gelmpm_material_gel_references_h

#include <gelmpm/material/flory_rehner_gel.h>

namespace GelMPM
{
  /**
   * How a gel deforms when it swells freely in a scene: in three dimensions (a 3D scene, and the
   * body of revolution of an axisymmetric one), or in plane strain (a 2D Cartesian scene, whose
   * out-of-plane stretch stays at lambda_0).
   */
  enum class SwellingKinematics
  {
    three_dimensional,
    plane_strain
  };

  /** A stress-free (or, for a bonded film, traction-free) swollen state of a gel. */
  struct SwollenState
  {
    /**
     * The stretch from the dry state: isotropic in 3D, in-plane in plane strain, the thickness
     * stretch of a bonded film.
     */
    double stretch_from_dry;
    /** The same stretch from the initial state (divided by lambda_0). */
    double stretch_from_initial;
    /** The volume ratio J from the dry state. */
    double J;
  };

  /**
   * The gel linearised about a stress-free swollen state at fixed mu (drained): an isotropic
   * solid (in plane strain, for in-plane strains) with Lamé's constants lambda and G_s in the
   * current configuration, c_ijkl = (1/J) F_jJ F_lL A_iJkL of the gel's tangent A = dP/dF.
   * Stresses in the unit of 'Shear modulus', lengths in the scene's, times in tau_d.
   */
  struct DrainedModuli
  {
    /** G_s = c_1212 (G lambda_x^2/J: G/lambda in 3D, G/lambda_0 in plane strain). */
    double shear_modulus;
    /** Lamé's lambda = c_1122 (J psi'' + psi' at equilibrium). */
    double lame;
    /** nu = lambda / (2 (lambda + G_s)). */
    double poisson_ratio;
    /** E = 2 G_s (1 + nu). */
    double young_modulus;
    /** E' = E / (1 - nu^2) = 4 G_s (lambda + G_s)/(lambda + 2 G_s): uniaxial stress, no strain out
     * of the plane. */
    double plane_strain_modulus;
    /** E / (1 - nu): equibiaxial stress in a plate. */
    double biaxial_modulus;
    /**
     * The permeability kappa = m / (k_BT/nu)^2 = D N nu (J - 1)/J of the solvent's volume flux
     * q = -kappa grad p, p = (k_BT/nu) mu (m: FloryRehnerGel::mobility()).
     */
    double permeability;
    /**
     * Biot's consolidation coefficient c = kappa (lambda + 2 G_s) = 2 (1 - nu)/(1 - 2 nu) G_s
     * kappa: the diffusivity of the volumetric strain, in units of L^2/tau_d.
     */
    double consolidation_coefficient;
  };

  /**
   * @brief The closed-form references of one Flory–Rehner gel that a scene is checked against:
   * free and laterally constrained swelling stretches at a bath's mu, the drained moduli and the
   * consolidation coefficient of the swollen state, the mu at which a bonded film's surface
   * reaches a given stretch ratio. Every value is computed from FloryRehnerGel's stress and
   * tangent (the gel law the solver assembles), scalar equations by TOMS 748 (Boost.Math) on a
   * bracket walked up from the dry state, so that the first root (the swelling branch) is found.
   */
  class GelReferences
  {
  public:
    /** The gel @p gel (its constants and lambda_0; plane strain keeps F_33 = lambda_0). */
    template <int dim>
    explicit GelReferences(const FloryRehnerGel<dim> &gel);

    /**
     * Free swelling at @p mu: in 3D F = lambda I with P = 0 (eq. (22)); in plane strain
     * F = diag(lambda, lambda, lambda_0) with P_11 = P_22 = 0. Throws std::domain_error if @p mu
     * is above the largest swelling chemical potential.
     */
    SwollenState
    free_swelling(const double mu, const SwellingKinematics kinematics) const;

    /**
     * A film bonded to a rigid substrate, laterally held at the initial stretch lambda_0 (uniaxial
     * swelling, paper §4.1): F = diag(lambda_0, lambda_0 s, lambda_0) with P_22 = 0 at @p mu; the
     * same in plane strain. s = h/H, also the surface's ratio of principal stretches
     * lambda_y/lambda_x that the creasing threshold is stated in (doc/own_scenes.md, section 7).
     */
    SwollenState
    constrained_swelling(const double mu) const;

    /** The mu at which constrained_swelling() has the stretch ratio @p s (P_22 is affine in mu). */
    double
    constrained_swelling_chemical_potential(const double s) const;

    /** The mu of the stress-free state free_swelling() at @p stretch_from_dry. */
    double
    free_swelling_chemical_potential(const double             stretch_from_dry,
                                     const SwellingKinematics kinematics) const;

    /** The drained moduli and c about free_swelling(@p mu, @p kinematics). */
    DrainedModuli
    drained_moduli(const double mu, const SwellingKinematics kinematics) const;

    const FloryRehnerGel<3> &
    gel() const;

  private:
    /** The 3D gel and the plane-strain one (F_33 = lambda_0) of the same constants. */
    FloryRehnerGel<3> gel_3d;
    FloryRehnerGel<2> gel_2d;
  };


  /**
   * Timoshenko's curvature of a bimetal strip (J. Opt. Soc. Am. 11 (1925) 233): two bonded layers
   * of thicknesses @p h_1, @p h_2 and moduli @p E_1, @p E_2 (the plane-strain or biaxial ones)
   * whose free strains differ by @p mismatch (layer 1's minus layer 2's),
   *   kappa = 6 eps (1 + m)^2 / (h [3 (1 + m)^2 + (1 + m n)(m^2 + 1/(m n))]),
   * m = h_1/h_2, n = E_1/E_2, h = h_1 + h_2; positive: the strip bends towards layer 2. With
   * m = n = 1, kappa = 3 eps / (2 h).
   */
  double
  timoshenko_curvature(const double mismatch,
                       const double h_1,
                       const double h_2,
                       const double E_1,
                       const double E_2);
} // namespace GelMPM

#endif
