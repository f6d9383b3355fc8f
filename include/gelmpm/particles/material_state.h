#ifndef gelmpm_particles_material_state_h
#define gelmpm_particles_material_state_h

#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/scene/material_regions.h>

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
} // namespace GelMPM

#endif
