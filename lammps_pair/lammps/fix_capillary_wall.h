/* -*- c++ -*- ----------------------------------------------------------
   capbridge — LAMMPS binding: fix capillary/wall

   Liquid bridges between the grains of pair style gran/capillary and flat walls, the
   inside of a z cylinder about the z axis, or the faces of a region:
     fix ID group capillary/wall xplane|yplane|zplane LO HI [angle DEG] [volume V]
     fix ID group capillary/wall zcylinder RADIUS [angle DEG] [volume V]
     fix ID group capillary/wall region REGION-ID [angle DEG] [volume V]
   (LO or HI may be NULL; a curved wall is its tangent plane at each grain; a region's
   faces are those of Region::surface, as fix wall/gran/region's, and may move).  The
   wall's contact is not ours: a stock fix wall/gran (or wall/gran/region) on the same
   walls gives it, and the forces add (its Coulomb limit reads its own contact force, which
   is eq. 12 of Richefeu 2007 as his eq. 1 defines f_n).  This fix adds the bridge's
   capillary force (the core's sphere-plane pair, r2 = CB_PLANE) and, with a viscous law, its
   viscous force.  The bridge of each grain and wall lives in a per-atom array of the fix
   (it migrates with the atom and is written to restart files).
   The liquid: in liquid mode fixed (or without fix capillary/liquid) a bridge forms at
   contact with the type pair's volume (or this fix's volume V); Protocol 1 distributes
   the liquid over the grain pairs and the grain-wall pairs (candidates()); under Protocols
   2 and 3
   fix capillary/liquid moves the grain's free liquid into the wall bridge and, at rupture,
   all of it back to the grain (the wall holds none): it advances these bridges with the
   pair's, through contacts() below.  See doc/fix_capillary_wall.rst.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(capillary/wall,FixCapillaryWall);
// clang-format on
#else

#ifndef LMP_FIX_CAPILLARY_WALL_H
#define LMP_FIX_CAPILLARY_WALL_H

#include "fix.h"

#include "capbridge.h"

#include <vector>

namespace LAMMPS_NS {

struct CapillaryBridges;
class FixCapillaryLiquid;

class FixCapillaryWall : public Fix {
 public:
  FixCapillaryWall(class LAMMPS *, int, char **);
  ~FixCapillaryWall() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  double compute_vector(int) override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

  // ---- used by fix capillary/liquid (Protocols 2, 3) ----
  // one owned grain of a wet type in this fix's group and one of its walls (a plane, the
  // cylinder, a region's face), which hold a bridge (or a mark) or touch
  struct Contact {
    int atom, wall;
    double gap;       // distance of the centre from the wall minus the radius
    double offset;    // height of the contact point above the grain's centre (Protocol 3)
    int wet;          // the grain may form a bridge (the liquid fix's group)
  };
  // this step's (kept in the fix, so that no step allocates)
  const std::vector<Contact> &contacts();
  // Protocol 1's: the grains within the rupture distance of a bridge of this volume
  void candidates(std::vector<Contact> &out, double volume);
  cb_bridge *bridge_at(int atom, int wall) const
  {
    return reinterpret_cast<cb_bridge *>(&state[atom][wall * CB_BRIDGE_DOUBLES]);
  }
  const cb_law *law_of(int atom) const { return laws[atom_type(atom)]; }
  // the partner ID of a wall in the protocols' draws and ties: negative, no atom's tag
  long long wall_key(int wall) const { return -(key_base + wall + 1); }
  // this rank's bridges and their liquid
  void census(double &count, double &liquid) const;

 protected:
  enum { MAX_WALLS = 2, CYLINDER = 3, REGION = 4 };
  // one wall a grain's bridge may reach this step
  struct Face {
    int wall;        // the bridge's slot: the plane or the cylinder, or the region's face
    int beyond;      // a region's face out of the grain's reach (holding a bridge or a mark)
    double gap;      // distance of the centre from the wall minus the radius
    double n[3];     // the wall's normal at the grain, towards its centre
    double v[3];     // the wall's velocity at the contact point (a moving region), else 0
  };
  int nwalls;                  // the bridges each grain keeps: planes, 1, or the region's cmax
  int axis[MAX_WALLS];         // 0, 1, 2: the plane's normal; CYLINDER, REGION
  double side[MAX_WALLS];      // +1: the grains are above the plane (LO), -1: below (HI)
  double position[MAX_WALLS];  // the plane's coordinate, or the cylinder's radius
  double wall_angle;           // keyword angle [rad]; < 0: the grains' own contact angle
  double volume_given;         // keyword volume; < 0: the type pair's
  char *region_id;             // REGION: the region's ID, and the region (found at init)
  class Region *region;
  std::vector<Face> grain_faces;         // faces()'s (kept in the fix: no step allocates)
  int key_base;                // wall_key's offset: the walls of the capillary/wall fixes before

  double **state;              // per atom: nwalls cb_bridge's
  CapillaryBridges *bridges;   // pair gran/capillary's type pairs and bridge events
  FixCapillaryLiquid *liquid;  // nullptr: no fix capillary/liquid
  int per_atom_liquid;         // Protocols 2, 3: the liquid fix advances the bridges
  int protocol1;               // Protocol 1: the liquid fix distributes, broken ones pool
  int liquid_groupbit;
  std::vector<cb_law> own_laws;          // per type: the law at the wall's angle
  std::vector<const cb_law *> laws;      // per type: the law of a wall bridge (nullptr: dry)
  std::vector<double> volumes;           // per type: the volume a bridge forms with (fixed)
  std::vector<Contact> step_contacts;    // contacts()'s

  double values[5];            // bridges, liquid, force on the walls (x, y, z)
  double wall_force[3];        // this rank's, at the last force evaluation
  bigint census_step;
  int timestep_warned;

  int atom_type(int atom) const;
  int parse_walls(int narg, char **arg);
  void derive_laws();
  void release_laws();
  void check_states();
  void check_timestep();
  void prepare_walls();
  const std::vector<Face> &faces(int atom, double reach, int with_beyond);
  double grain_reach(int atom) const;
  double bridge_force(int atom, int wall, double gap, cb_bridge *bridge);
  double viscous_normal(int atom, const Face &face, const cb_bridge *bridge, double *ft);
  [[noreturn]] void fail(int status, const char *what, int atom, double gap, double volume) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
