/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   The only place where LAMMPS releases differ for cellsph: every other file is written once.
   LMP_VERSION_NUM (YYYYMMDD) comes from the build, parsed from the host's src/version.h.
------------------------------------------------------------------------- */

#ifndef LMP_CELL_COMPAT_H
#define LMP_CELL_COMPAT_H

#include "comm.h"
#include "neighbor.h"

#include <cstring>

#ifndef LMP_VERSION_NUM
#error "LMP_VERSION_NUM must be defined by the build (parsed from LAMMPS src/version.h)"
#endif

// 24Mar2022: neighbor->add_request() and comm->forward_comm(style) replace the older API
#define CELL_NEW_NEIGH_COMM (LMP_VERSION_NUM >= 20220324)

#if !CELL_NEW_NEIGH_COMM
#include "neigh_request.h"
#endif

namespace LAMMPS_NS {
class Pair;
class Fix;

namespace CellCompat {

  enum { REQ_DEFAULT = 0, REQ_FULL = 1 << 0, REQ_OCCASIONAL = 1 << 4 };

#if CELL_NEW_NEIGH_COMM
  template <class Style>
  NeighRequest *request_list(Neighbor *neighbor, Style *style, int, int flags)
  {
    return neighbor->add_request(style, flags);
  }
  template <class Style> void forward_comm(Comm *comm, Style *style)
  {
    comm->forward_comm(style);
  }
  template <class Style> void reverse_comm(Comm *comm, Style *style)
  {
    comm->reverse_comm(style);
  }
#else
  inline NeighRequest *configure(NeighRequest *rq, int flags)
  {
    if (flags & REQ_FULL) {
      rq->half = 0;
      rq->full = 1;
    }
    if (flags & REQ_OCCASIONAL) rq->occasional = 1;
    return rq;
  }
  // request() may reallocate the requests array: index it only after the call
  inline NeighRequest *request_list(Neighbor *neighbor, Pair *style, int instance, int flags)
  {
    const int irq = neighbor->request(style, instance);
    return configure(neighbor->requests[irq], flags);
  }
  inline NeighRequest *request_list(Neighbor *neighbor, Fix *style, int instance, int flags)
  {
    const int irq = neighbor->request(style, instance);
    NeighRequest *rq = neighbor->requests[irq];
    rq->pair = 0;
    rq->fix = 1;
    return configure(rq, flags);
  }
  inline void forward_comm(Comm *comm, Pair *style)
  {
    comm->forward_comm_pair(style);
  }
  inline void reverse_comm(Comm *comm, Pair *style)
  {
    comm->reverse_comm_pair(style);
  }
  inline void forward_comm(Comm *comm, Fix *style)
  {
    comm->forward_comm_fix(style);
  }
  inline void reverse_comm(Comm *comm, Fix *style)
  {
    comm->reverse_comm_fix(style);
  }
#endif

  // the ghost cutoff of comm mode single: the larger of comm_modify cutoff and the neighbour
  // cutoff, the line of Comm::get_comm_cutoff() that 29 Sep 2021 and later releases share (called
  // here, that function would print again the warnings that comm->setup() prints)
  inline double ghost_cutoff(Comm *comm, Neighbor *neighbor)
  {
    return comm->cutghostuser > neighbor->cutneighmax ? comm->cutghostuser : neighbor->cutneighmax;
  }

  // yes/no/on/off/true/false as utils::logical() in current LAMMPS; -1 if none of these
  inline int logical(const char *word)
  {
    for (const char *yes : {"yes", "on", "true"})
      if (strcmp(word, yes) == 0) return 1;
    for (const char *no : {"no", "off", "false"})
      if (strcmp(word, no) == 0) return 0;
    return -1;
  }

}    // namespace CellCompat
}    // namespace LAMMPS_NS

#endif
