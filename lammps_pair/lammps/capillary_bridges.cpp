/* ----------------------------------------------------------------------
   capbridge — LAMMPS binding: the bridges of pair style gran/capillary (see the header)

   The one out-of-line member of CapillaryBridges: the error of a failed core call in a
   bridge loop, named by type pair and law, shared by the pair's loops and the fix's
   protocols (a file of its own: it belongs to neither).
------------------------------------------------------------------------- */

#include "capillary_bridges.h"

#include "error.h"

using namespace LAMMPS_NS;

void CapillaryBridges::fail_cb(Error *error, int status, const char *what, int itype, int jtype,
                               double r1, double r2, double vol, double gap) const
{
  error->one(FLERR, "pair gran/capillary: {} failed for types {} {} (law '{}', r1 = {}, "
             "r2 = {}, volume = {}, gap = {}): {}", what, itype, jtype,
             law_text[type_pair(itype, jtype).law_index], r1, r2, vol, gap,
             cb_status_message((cb_status) status));
}
