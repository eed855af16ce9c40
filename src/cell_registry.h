/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   The cells of a group and where their sums meet (doc/model.md §5.2). A cell is a molecule ID > 0.
   Each cell has a home rank, fixed from one init() to the next: the rank that held the cell's
   lowest atom ID then. Ranks sum what they own of the cells they touch, in columns the caller
   chooses; reduce() sends each touched cell's partial sums to its home rank only (MPI_Alltoall of
   counts, MPI_Alltoallv of rows), which totals them and runs the cell's per-cell logic;
   scatter() sends per-cell results back to the ranks that touch the cell. The cost per rank grows
   with the cells it touches, not with all cells; allgather() (every cell on every rank) is for
   outputs and networks, O(cells).
------------------------------------------------------------------------- */

#ifndef LMP_CELL_REGISTRY_H
#define LMP_CELL_REGISTRY_H

#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class CellRegistry : protected Pointers {
 public:
  CellRegistry(class LAMMPS *, const std::string &command, int igroup);
  // the style named in the messages from here on
  void name(const std::string &who) { command = who; }

  // the cells: distinct molecule IDs > 0 of the group's atoms on all ranks (collective, O(cells))
  void find_cells();
  // each cell's reference point (mean unwrapped position of its atoms of type walltype) and home
  // rank (collective, O(cells)); once per run
  void init(int walltype);
  // each owned atom's cell and the cells this rank touches (local, O(atoms))
  void map_atoms();

  int ncell() const { return (int) ids.size(); }
  tagint id(int c) const { return ids[c]; }
  // every cell's ID, ascending (index c is cell c)
  const std::vector<tagint> &cell_ids() const { return ids; }
  // index of a cell ID, -1 if it is not a cell of the group
  int index(tagint molecule) const;
  int home(int c) const { return homes[c]; }
  // false before the first init() after find_cells()
  bool has_homes() const { return !ids.empty() && homes.size() == ids.size(); }
  // this rank's home cells, ascending; home_slot(c) is c's position there, -1 elsewhere
  const std::vector<int> &home_cells() const { return mine; }
  int home_slot(int c) const { return homeslot[c]; }
  // reference point of cell c (unwrapped), the origin of its wall positions
  const double *reference(int c) const { return &ref[3 * c]; }
  // cell index of each owned atom at the last map_atoms(), -1 if in no cell of the group
  const std::vector<int> &cell_of_atom() const { return cellof; }
  // cells with owned atoms of the group on this rank, ascending; slot(c) is c's position there
  const std::vector<int> &touched() const { return seen; }
  int slot(int c) const { return touchslot[c]; }

  // part: ncol sums per touched cell; total: their sums over all ranks, ncol per home cell.
  // Collective; the totals of a cell are its home's partial sums plus the others' in rank order
  void reduce(int ncol, const std::vector<double> &part, std::vector<double> &total);
  // values: ncol per home cell; out: those of each touched cell (the pattern of the last reduce)
  void scatter(int ncol, const std::vector<double> &values, std::vector<double> &out) const;
  // values: ncol per home cell; out: ncol per cell on every rank, in cell order. Collective,
  // O(cells) per rank: outputs and cell-to-cell networks
  void allgather(int ncol, const std::vector<double> &values, std::vector<double> &out) const;
  // values: ncol per home cell; out on rank 0 only, ncol per cell in cell order (restart files)
  void gather(int ncol, const std::vector<double> &values, std::vector<double> &out) const;

  // rows of ncol doubles, each led by its cell index (and ntag IDs per row in tags), to the home
  // rank of that cell; got (and got_tags) receive the rows of this rank's home cells from every
  // rank, in rank order. Collective (MPI_Alltoall of counts, MPI_Alltoallv of rows), O(rows)
  void send_home(int ncol, const std::vector<double> &rows, std::vector<double> &got, int ntag = 0,
                 const std::vector<tagint> *tags = nullptr,
                 std::vector<tagint> *got_tags = nullptr) const;

  // per-cell problems found on the home ranks: the message of the lowest failed cell index
  // (failed = ncell() if none) stops every rank with error->all; each rank's warnings are printed
  // by rank 0. Collective, one MPI_Allreduce of 2 ints when nothing happened
  void settle(int failed, const std::string &message, const std::vector<std::string> &warnings);

 private:
  std::string command, group_name;
  int groupbit;
  std::vector<tagint> ids;            // cell (molecule) IDs, ascending
  std::vector<int> dense;             // index of ID ids[0] + k, -1 if none; empty: IDs sparse
  std::vector<int> homes;             // home rank of each cell
  std::vector<int> mine, homeslot;    // home cells of this rank, slot of each cell among them
  std::vector<double> ref;            // reference point of each cell (unwrapped), 3 per cell
  std::vector<int> cellof, seen, touchslot;
  // the exchange of the last reduce(): touched cells sent to each rank (in rank order) and the
  // home slots received from each, with per-rank counts and offsets (in rows)
  std::vector<int> sendcells, recvslots, sendcounts, senddispls, recvcounts, recvdispls;
  std::vector<double> sendbuf, recvbuf;

  void alltoallv(int ncol, const std::vector<int> &scounts, const std::vector<int> &sdispls,
                 const std::vector<int> &rcounts, const std::vector<int> &rdispls,
                 const double *send, double *recv) const;
};

}    // namespace LAMMPS_NS

#endif
