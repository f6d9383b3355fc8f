#ifndef gelmpm_assembly_face_separation_h
#define gelmpm_assembly_face_separation_h

#include <gelmpm/assembly/point_cache.h>
#include <gelmpm/bspline/extended_bspline_space.h>

#include <deal.II/base/tensor.h>
#include <deal.II/particles/particle_handler.h>

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace GelMPM
{
  /** Per point, the indices of its material neighbours (compressed rows). */
  struct PointGraph
  {
    std::vector<unsigned int> offsets{0};
    std::vector<unsigned int> targets;

    /** The neighbours of point @p i. */
    std::pair<const unsigned int *, const unsigned int *>
    neighbours(const unsigned int i) const
    {
      return {targets.data() + offsets[i], targets.data() + offsets[i + 1]};
    }
  };


  namespace Separation
  {
    struct SupportParts;
  }


  /**
   * @brief Which points of a displacement function's support are one piece of material, and
   * which further pieces are faces of their own that take a copy of it ('Contact/Self contact/
   * Separate faces', doc/method.md, "Two faces on one grid"). PointCache asks it at every
   * gather() and numbers and groups the copies.
   *
   * Two points are material neighbours when their distance in the initial configuration is at
   * most 1.5 times the larger of their spacings, a surface point never with a point in front of
   * it nor with a surface point facing it (N_0 . N_0 < 0). For each extended u function whose
   * support holds a surface point of the chosen pieces, the points of its support (the blocks
   * whose DoFs include it) fall into parts connected by neighbours within the support. Where two
   * or more parts hold such a surface point and more than 1 % of the function's weight sum V_n |N|
   * over the volume points, the part of most points keeps the function and each other one takes
   * a copy; the rest (slivers cut off by the edge of the support) keep the function, and so does
   * a part whose surface points lie within 'Minimum arc length' of the keeper's along the surface
   * (a path over neighbouring surface points in the initial configuration): the flanks next to a
   * fold's tip, which the self-contact does not pair. A surface point of the pieces is evaluated
   * in the cell (leaf) of one of its neighbouring volume points, so that it does not take the
   * functions of another part lying in its cell.
   */
  template <int dim>
  class FaceSeparation
  {
  public:
    using particle_iterator = typename dealii::Particles::ParticleHandler<dim>::particle_iterator;

    /** The points of a step grouped into blocks by their cells' own functions (PointCache). */
    struct Grouping
    {
      const std::vector<PointRecord<dim>> &points;
      const std::vector<PointBlock>       &blocks;
      /** Per sorted point, its index among the unsorted records. */
      const std::vector<unsigned int> &order;
      /** The u shape values of the points (PointRecord::u_offset). */
      const std::vector<double>       &u_values;
      const ExtendedBSplineSpace<dim> &u;
    };

    /**
     * @p pieces flags the boundary pieces whose surface points take part; @p along_surface is
     * the distance along the surface within which faces stay together.
     */
    FaceSeparation(std::vector<bool> pieces, const double along_surface, const bool axisymmetric);

    /** Whether record @p r is a surface point of the pieces whose faces are separated. */
    bool
    separates(const PointRecord<dim> &r) const
    {
      return r.kind != PointKind::volume && r.piece >= 0 && pieces[r.piece];
    }

    /** The material neighbours of the step's records @p unsorted, of the particles @p its. */
    void
    find_neighbours(const std::vector<PointRecord<dim>>  &unsorted,
                    const std::vector<particle_iterator> &its);

    /**
     * Move each separated surface point of @p unsorted whose cell and piece hold none of its
     * neighbouring volume points to those of its nearest one (in the initial configuration).
     */
    void
    anchor_surface_points(const std::vector<PointRecord<dim>> &unsorted,
                          std::vector<unsigned int>           &cells,
                          std::vector<unsigned int>           &pieces) const;

    /**
     * Per sorted point of @p grouping, the copies it uses: (position in its block's u DoFs,
     * copy's DoF), copy k being u DoF u.n_dofs() + k of the function @p copy_of[k] (appended).
     */
    std::vector<std::vector<std::pair<unsigned int, unsigned int>>>
    copies_of_points(const Grouping &grouping, std::vector<unsigned int> &copy_of);

    /** The ties of the weak copies of the last copies_of_points(). */
    const std::vector<CopyTie> &
    ties() const
    {
      return ties_;
    }

    /** A face's share of a function's weight below which its copy is tied (CopyTie). */
    static constexpr double weak_share = 0.25;

  private:
    /** A copy whose face holds less than weak_share of its function's weight. */
    struct WeakCopy
    {
      unsigned int              copy, function;
      std::vector<unsigned int> members, others;
      double                    total;
    };

    /** What the donor search of one step shares over its weak copies. */
    struct DonorSearch
    {
      /** Per cell, the number of blocks in it. */
      std::map<unsigned int, unsigned int> blocks_of_cell;
      /** Per sorted point, 0 unseen, 1 reached, 2 barred: reached_from_face()'s scratch, left
       * all 0. */
      std::vector<unsigned char> state;
    };

    /**
     * Tie each copy of @p weak (CopyTie); a weak copy that cannot be tied is removed from
     * @p copies and @p copy_of (its face keeps the function) and the copies are numbered anew.
     */
    void
    tie_weak_copies(const Grouping                                                  &grouping,
                    std::vector<std::vector<std::pair<unsigned int, unsigned int>>> &copies,
                    std::vector<unsigned int>                                       &copy_of,
                    const std::vector<WeakCopy>                                     &weak);

    /**
     * The tie of @p weak (its face's members and the support's other points, sorted indices) to
     * the nearest interior cell reached from its face without crossing the other points, given
     * the copies @p copies each point uses; false where no such cell lies next to the function.
     */
    bool
    tie_weak_copy(const Grouping                                                        &grouping,
                  const std::vector<std::vector<std::pair<unsigned int, unsigned int>>> &copies,
                  const std::vector<bool> &weak_copies,
                  const WeakCopy          &weak,
                  DonorSearch             &search,
                  CopyTie                 &tie) const;

    /**
     * The block whose cell's functions @p weak is extrapolated from (tie_weak_copy()), its
     * cell's lowest function multi-index into @p corner; -1 if none lies next to the function.
     */
    int
    donor_block(const Grouping                                                        &grouping,
                const std::vector<std::vector<std::pair<unsigned int, unsigned int>>> &copies,
                const std::vector<bool>                                               &weak_copies,
                const WeakCopy                                                        &weak,
                DonorSearch                                                           &search,
                std::array<int, dim> &corner) const;

    /**
     * The sorted points reached from @p weak's face over material neighbours, never into the
     * support's other parts, within 2(q+1) cells of the face's centre; @p state the scratch.
     */
    std::vector<unsigned int>
    reached_from_face(const Grouping             &grouping,
                      const WeakCopy             &weak,
                      std::vector<unsigned char> &state) const;

    /**
     * Per record of @p unsorted, its spacing in the initial configuration (V_0^{1/dim},
     * A_0^{1/(dim-1)}, revolved measures divided by 2 pi R_0) and, for surface points, the unit
     * N_0.
     */
    void
    reference_spacing(const std::vector<PointRecord<dim>>  &unsorted,
                      const std::vector<particle_iterator> &its,
                      std::vector<double>                  &spacing,
                      std::vector<dealii::Tensor<1, dim>>  &normal_0) const;

    /** Per u DoF whose support holds a separated surface point, the blocks of its support. */
    std::vector<std::vector<unsigned int>>
    blocks_of_separated_functions(const Grouping &grouping) const;

    /**
     * The points of the support of u DoF @p d (the points of @p blocks) and the parts they fall
     * into; @p local and @p stamp are scratch arrays over the points.
     */
    Separation::SupportParts
    parts_of_support(const Grouping                  &grouping,
                     const unsigned int               d,
                     const std::vector<unsigned int> &blocks,
                     std::vector<unsigned int>       &local,
                     std::vector<unsigned int>       &stamp) const;

    /** The parts of @p support that are faces of their own. */
    std::vector<unsigned int>
    faces_of_support(Separation::SupportParts &support) const;

    /**
     * Whether a path over neighbouring surface points, no longer than along_surface in the
     * initial configuration, joins a point of @p from to one of @p to (unsorted indices).
     */
    bool
    near_along_surface(const Grouping                  &grouping,
                       const std::vector<unsigned int> &from,
                       const std::vector<unsigned int> &to) const;

    const std::vector<bool> pieces;
    const double            along_surface;
    const bool              axisymmetric;
    // The step's neighbours (unsorted indices) and, per unsorted record, its sorted index.
    PointGraph                graph;
    std::vector<unsigned int> sorted_of;
    std::vector<CopyTie>      ties_;
    std::vector<unsigned int> control_point_of_dof;
  };
} // namespace GelMPM

#endif
