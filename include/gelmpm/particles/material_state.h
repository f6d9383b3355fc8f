#ifndef gelmpm_particles_material_state_h
#define gelmpm_particles_material_state_h

#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/scene/material_regions.h>

#include <deal.II/base/tensor.h>

namespace GelMPM
{
  /**
   * @brief The material state of a point: its region and the gel whose constants the gel law
   * is evaluated with there (doc/architecture.md, "Several gels are one table of gels").
   */
  template <int dim>
  struct MaterialState
  {
    unsigned int               region;
    const FloryRehnerGel<dim> *gel;
  };


  /**
   * The material state of the point whose property array is @p properties, in the body of the
   * gels @p regions: the one place where a point is mapped to its constants. The point cache
   * records it once per step (PointRecord::region and PointRecord::gel, which the gel law's
   * call sites in the assembly read); the observables, the balances and the output ask it here.
   * Constants that vary in space (X_0 is among the properties) or in time change this function
   * and what its gel points to, not the call sites of the gel law.
   */
  template <int dim, typename Properties>
  inline MaterialState<dim>
  material_state_of(const MaterialRegions<dim> &regions, const Properties &properties)
  {
    const unsigned int region = region_of_point<dim>(properties);
    return {region, &regions[region]};
  }


  /** F_n F_0 of the point whose property array is @p properties (PropertyLayout::F). */
  template <int dim, typename Properties>
  inline dealii::Tensor<2, dim>
  deformation_gradient_of(const Properties &properties)
  {
    dealii::Tensor<2, dim> F;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F[i][j] = properties[PropertyLayout<dim>::F + i * dim + j];
    return F;
  }


  /** The volume ratio J (dry state to Omega_n) of the point: its gel on its F and F_33. */
  template <int dim, typename Properties>
  inline double
  volume_ratio_of(const MaterialRegions<dim> &regions, const Properties &properties)
  {
    return material_state_of(regions, properties)
      .gel->J(deformation_gradient_of<dim>(properties), out_of_plane_stretch_of<dim>(properties));
  }
} // namespace GelMPM

#endif
