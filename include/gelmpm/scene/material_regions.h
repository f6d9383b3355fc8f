#ifndef gelmpm_scene_material_regions_h
#define gelmpm_scene_material_regions_h

#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/scene/expression.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The gels a body is made of: the section "Material" for the body (or the rest of it),
   * and with "Material/Regions = a, b, ..." a subsection "Material/<name>" per region that
   * selects part of the body and gives it its own constants. Interfaces between regions are
   * bonded: a body is one set of material points on one grid, and each point carries the gel of
   * its region.
   *
   * A region is chosen by a 'Selector', an expression in the initial position x, y (, z) that is
   * nonzero inside the region, or by a 'Mesh group', the name of a physical group of dimension
   * dim of the Gmsh mesh of 'Geometry/Mesh file'. A point belongs to at most one region
   * (overlapping regions are an input error) and to the body's own material when it belongs to
   * none; each region must hold some volume point.
   *
   * Constants left empty in a region are those of "Material". Every gel of a body shares the
   * solvent and the temperature: k_BT/nu = G/(N nu) is one number, so that a region gives its
   * crosslink density by 'N nu' or by 'Shear modulus' (the other follows), or by both when they
   * agree.
   *
   * The initial state: every region is stress-free in equilibrium with one chemical potential
   * mu_0, the one of "Material" ('Initial state'); each region's initial stretch lambda_0 follows
   * from eq. (22) with its own chi and N nu. mu is one continuous field: a jump of mu_0 at an
   * interface could not be represented, and different lambda_0 at one mu_0 is what a bonded
   * stack of different gels swollen in one bath has.
   *
   * Region 0 is the body's own material; region k > 0 is the k-th name of 'Regions'. With no
   * regions (every paper scene) there is one gel and nothing is evaluated per point.
   */
  template <int dim>
  class MaterialRegions
  {
  public:
    /** One gel, the Table 1 material. */
    MaterialRegions() = default;

    /** One gel: @p gel everywhere. */
    explicit MaterialRegions(const FloryRehnerGel<dim> &gel)
      : gels{gel}
    {}

    /** Declare "Material/<name>" for each of @p names ("Material/Regions" itself is declared by
     * SceneStructure, which reads it first). */
    static void
    declare_parameters(dealii::ParameterHandler &prm, const std::vector<std::string> &names);

    /**
     * Read the regions' subsections, the body's own material being @p base (parsed already).
     * Throws InputError on a region without or with two ways of selecting, an expression that
     * cannot be parsed, a non-physical constant, G and N nu that disagree with the body's
     * k_BT/nu, or a mu_0 at which a region's gel has no stress-free swollen state.
     */
    void
    parse_parameters(dealii::ParameterHandler       &prm,
                     const std::vector<std::string> &names,
                     const FloryRehnerGel<dim>      &base);

    /** 1 + the number of regions. */
    unsigned int
    size() const;

    /** The gel of region @p region (0: the body's own). */
    const FloryRehnerGel<dim> &
    operator[](const unsigned int region) const;

    /** The region's name ("Material" for region 0). */
    const std::string &
    name(const unsigned int region) const;

    /** Whether a region is chosen by a Gmsh physical group. */
    bool
    uses_mesh_groups() const;

    /**
     * The region of a point at the initial position @p X0 in the mesh cell of the physical group
     * @p group_name (empty: none, or no mesh). Throws InputError if two regions select it.
     */
    unsigned int
    region_of(const dealii::Point<dim> &X0, const std::string &group_name = "") const;

    /**
     * Throws InputError naming the region's selector if a region holds no volume point
     * (@p counts: volume points per region, over all ranks), or a group that is not a volume
     * group of the mesh (@p volume_groups: the names of the mesh's groups of dimension dim).
     */
    void
    check_populated(const std::vector<unsigned long> &counts) const;

    void
    check_mesh_groups(const std::vector<std::string> &volume_groups,
                      const std::vector<std::string> &boundary_groups) const;

    /**
     * The smallest over the gels of FloryRehnerGel::largest_swelling_chemical_potential(): the
     * largest bath in which every region has a swollen equilibrium (@p axisymmetric: in a 2D
     * axisymmetric scene, whose gels swell in 3D).
     */
    double
    largest_swelling_chemical_potential(const bool axisymmetric = false) const;

  private:
    struct Region
    {
      std::string                            name;
      std::string                            selector_text;
      std::string                            mesh_group;
      std::unique_ptr<PointNormalExpression> selector;
    };
    /** The selector of @p region at @p X0; InputError naming it where it is not a number. */
    static double
    selector_value(const Region &region, const dealii::Point<dim> &X0);

    /** The region's selector or mesh group, from its subsection (entered). */
    static Region
    parse_selection(dealii::ParameterHandler &prm, const std::string &name);

    /** The region's gel, from its subsection (entered), empty entries from @p base. */
    static FloryRehnerGel<dim>
    parse_gel(dealii::ParameterHandler  &prm,
              const std::string         &name,
              const FloryRehnerGel<dim> &base);

    std::vector<FloryRehnerGel<dim>> gels = {FloryRehnerGel<dim>()};
    std::vector<Region>              regions; // regions[k] is region k + 1
    std::string                      base_name = "Material";
  };
} // namespace GelMPM

#endif
