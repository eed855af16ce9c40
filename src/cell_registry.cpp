/* ----------------------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
------------------------------------------------------------------------- */

#include "cell_registry.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"

#include <algorithm>
#include <climits>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

CellRegistry::CellRegistry(LAMMPS *lmp, const std::string &command_in, int igroup) :
    Pointers(lmp), command(command_in), group_name(group->names[igroup]),
    groupbit(group->bitmask[igroup])
{
}

/* ---------------------------------------------------------------------- */

void CellRegistry::find_cells()
{
  std::vector<tagint> local;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && atom->molecule[i] > 0) local.push_back(atom->molecule[i]);
  std::sort(local.begin(), local.end());
  local.erase(std::unique(local.begin(), local.end()), local.end());

  const int n = (int) local.size();
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int p = 1; p < comm->nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  ids.resize(displs.back() + counts.back());
  MPI_Allgatherv(local.data(), n, MPI_LMP_TAGINT, ids.data(), counts.data(), displs.data(),
                 MPI_LMP_TAGINT, world);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  if (ids.empty())
    error->all(FLERR, "{}: group {} has no atoms with a molecule (cell) ID > 0", command,
               group_name);
  // index() by a table where the IDs are dense (cellgen numbers its cells 1 to N), else by a
  // binary search
  dense.clear();
  const tagint span = ids.back() - ids.front() + 1;
  if (span <= 4 * (tagint) ids.size()) {
    dense.assign(span, -1);
    for (int c = 0; c < (int) ids.size(); c++) dense[ids[c] - ids.front()] = c;
  }
}

/* ----------------------------------------------------------------------
   reference point = mean unwrapped position of the cell's wall atoms; home = the rank holding the
   cell's lowest atom ID of the group
------------------------------------------------------------------------- */

void CellRegistry::init(int walltype)
{
  const int n = ncell();
  std::vector<double> sum(4 * (size_t) n, 0.0), all(4 * (size_t) n);
  std::vector<tagint> lowest(n, MAXTAGINT), lowest_all(n);
  double xu[3];
  for (int i = 0; i < atom->nlocal; i++) {
    const int c = (atom->mask[i] & groupbit) ? index(atom->molecule[i]) : -1;
    if (c < 0) continue;
    lowest[c] = std::min(lowest[c], atom->tag[i]);
    if (atom->type[i] != walltype) continue;
    domain->unmap(atom->x[i], atom->image[i], xu);
    for (int d = 0; d < 3; d++) sum[4 * c + d] += xu[d];
    sum[4 * c + 3] += 1.0;
  }
  MPI_Allreduce(sum.data(), all.data(), 4 * n, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(lowest.data(), lowest_all.data(), n, MPI_LMP_TAGINT, MPI_MIN, world);
  ref.assign(3 * (size_t) n, 0.0);
  for (int c = 0; c < n; c++)
    if (all[4 * c + 3] > 0.0)
      for (int d = 0; d < 3; d++) ref[3 * c + d] = all[4 * c + d] / all[4 * c + 3];

  std::vector<int> holder(n);
  for (int c = 0; c < n; c++) holder[c] = lowest[c] == lowest_all[c] ? comm->me : -1;
  homes.resize(n);
  MPI_Allreduce(holder.data(), homes.data(), n, MPI_INT, MPI_MAX, world);
  mine.clear();
  homeslot.assign(n, -1);
  for (int c = 0; c < n; c++)
    if (homes[c] == comm->me) {
      homeslot[c] = (int) mine.size();
      mine.push_back(c);
    }
  touchslot.assign(n, -1);
  seen.clear();
}

/* ---------------------------------------------------------------------- */

void CellRegistry::map_atoms()
{
  for (int c : seen) touchslot[c] = -1;
  seen.clear();
  cellof.assign(atom->nlocal, -1);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int c = index(atom->molecule[i]);
    cellof[i] = c;
    if (c >= 0 && touchslot[c] < 0) {
      touchslot[c] = 0;
      seen.push_back(c);
    }
  }
  std::sort(seen.begin(), seen.end());
  for (int k = 0; k < (int) seen.size(); k++) touchslot[seen[k]] = k;
}

/* ---------------------------------------------------------------------- */

int CellRegistry::index(tagint molecule) const
{
  if (!dense.empty()) {
    const tagint k = molecule - ids.front();
    return k >= 0 && k < (tagint) dense.size() ? dense[k] : -1;
  }
  auto it = std::lower_bound(ids.begin(), ids.end(), molecule);
  return (it != ids.end() && *it == molecule) ? (int) (it - ids.begin()) : -1;
}

/* ----------------------------------------------------------------------
   MPI_Alltoallv of rows of ncol doubles, counts and offsets in rows
------------------------------------------------------------------------- */

void CellRegistry::alltoallv(int ncol, const std::vector<int> &scounts,
                             const std::vector<int> &sdispls, const std::vector<int> &rcounts,
                             const std::vector<int> &rdispls, const double *send,
                             double *recv) const
{
  const int nprocs = comm->nprocs;
  std::vector<int> sc(nprocs), sd(nprocs), rc(nprocs), rd(nprocs);
  for (int p = 0; p < nprocs; p++) {
    sc[p] = ncol * scounts[p];
    sd[p] = ncol * sdispls[p];
    rc[p] = ncol * rcounts[p];
    rd[p] = ncol * rdispls[p];
  }
  MPI_Alltoallv(send, sc.data(), sd.data(), MPI_DOUBLE, recv, rc.data(), rd.data(), MPI_DOUBLE,
                world);
}

/* ----------------------------------------------------------------------
   partial sums of the touched cells to their home ranks, totals there (doc/model.md §5.2)
------------------------------------------------------------------------- */

void CellRegistry::reduce(int ncol, const std::vector<double> &part, std::vector<double> &total)
{
  const int nprocs = comm->nprocs, me = comm->me;
  sendcounts.assign(nprocs, 0);
  for (int c : seen)
    if (homes[c] != me) sendcounts[homes[c]]++;
  senddispls.assign(nprocs, 0);
  for (int p = 1; p < nprocs; p++) senddispls[p] = senddispls[p - 1] + sendcounts[p - 1];
  recvcounts.resize(nprocs);
  MPI_Alltoall(sendcounts.data(), 1, MPI_INT, recvcounts.data(), 1, MPI_INT, world);
  recvdispls.assign(nprocs, 0);
  for (int p = 1; p < nprocs; p++) recvdispls[p] = recvdispls[p - 1] + recvcounts[p - 1];
  const int nsend = senddispls.back() + sendcounts.back();
  const int nrecv = recvdispls.back() + recvcounts.back();

  // each row: the cell index, then its ncol sums
  const int width = ncol + 1;
  sendcells.resize(nsend);
  sendbuf.resize((size_t) width * nsend);
  std::vector<int> next(senddispls);
  for (int k = 0; k < (int) seen.size(); k++) {
    const int c = seen[k];
    if (homes[c] == me) continue;
    const int row = next[homes[c]]++;
    sendcells[row] = c;
    double *s = &sendbuf[(size_t) width * row];
    s[0] = c;
    std::copy_n(&part[(size_t) ncol * k], ncol, s + 1);
  }
  recvbuf.resize((size_t) width * nrecv);
  alltoallv(width, sendcounts, senddispls, recvcounts, recvdispls, sendbuf.data(), recvbuf.data());

  // the home's own sums first, then the other ranks' in rank order
  total.assign((size_t) ncol * mine.size(), 0.0);
  for (int k = 0; k < (int) seen.size(); k++)
    if (homes[seen[k]] == me)
      std::copy_n(&part[(size_t) ncol * k], ncol, &total[(size_t) ncol * homeslot[seen[k]]]);
  recvslots.resize(nrecv);
  for (int row = 0; row < nrecv; row++) {
    const double *r = &recvbuf[(size_t) width * row];
    const int h = homeslot[(int) r[0]];
    if (h < 0) error->one(FLERR, "{}: rank {} got the sums of another rank's cell", command, me);
    recvslots[row] = h;
    double *t = &total[(size_t) ncol * h];
    for (int k = 0; k < ncol; k++) t[k] += r[k + 1];
  }
}

/* ----------------------------------------------------------------------
   home values back to the ranks that sent the cell's sums in the last reduce()
------------------------------------------------------------------------- */

void CellRegistry::scatter(int ncol, const std::vector<double> &values,
                           std::vector<double> &out) const
{
  const int me = comm->me;
  const int nrecv = (int) recvslots.size(), nsend = (int) sendcells.size();
  std::vector<double> back((size_t) ncol * nrecv), got((size_t) ncol * nsend);
  for (int row = 0; row < nrecv; row++)
    std::copy_n(&values[(size_t) ncol * recvslots[row]], ncol, &back[(size_t) ncol * row]);
  alltoallv(ncol, recvcounts, recvdispls, sendcounts, senddispls, back.data(), got.data());
  out.assign((size_t) ncol * seen.size(), 0.0);
  for (int k = 0; k < (int) seen.size(); k++)
    if (homes[seen[k]] == me)
      std::copy_n(&values[(size_t) ncol * homeslot[seen[k]]], ncol, &out[(size_t) ncol * k]);
  for (int row = 0; row < nsend; row++)
    std::copy_n(&got[(size_t) ncol * row], ncol, &out[(size_t) ncol * touchslot[sendcells[row]]]);
}

/* ----------------------------------------------------------------------
   variable rows to the home ranks of their cells (wall triangles, fluid positions)
------------------------------------------------------------------------- */

void CellRegistry::send_home(int ncol, const std::vector<double> &rows, std::vector<double> &got,
                             int ntag, const std::vector<tagint> *tags,
                             std::vector<tagint> *got_tags) const
{
  const int nprocs = comm->nprocs, me = comm->me;
  const int n = (int) (rows.size() / ncol);
  std::vector<int> scounts(nprocs, 0), sdispls(nprocs, 0), rcounts(nprocs), rdispls(nprocs, 0);
  for (int r = 0; r < n; r++) scounts[homes[(int) rows[(size_t) ncol * r]]]++;
  MPI_Alltoall(scounts.data(), 1, MPI_INT, rcounts.data(), 1, MPI_INT, world);
  for (int p = 1; p < nprocs; p++) rdispls[p] = rdispls[p - 1] + rcounts[p - 1];
  const int nrecv = rdispls.back() + rcounts.back();
  // this rank's own home rows go straight into got (at rdispls[me]), not through MPI
  scounts[me] = rcounts[me] = 0;
  for (int p = 1; p < nprocs; p++) sdispls[p] = sdispls[p - 1] + scounts[p - 1];
  const int nsend = sdispls.back() + scounts.back();

  // the other rows in the order of their home ranks; order[k]: the row of send row k, then the
  // rows kept here
  std::vector<int> order(n), next(sdispls);
  std::vector<double> send((size_t) ncol * nsend);
  got.resize((size_t) ncol * nrecv);
  int kept = nsend;
  for (int r = 0; r < n; r++) {
    const int p = homes[(int) rows[(size_t) ncol * r]];
    const int k = p == me ? kept++ : next[p]++;
    order[k] = r;
    double *to =
        p == me ? &got[(size_t) ncol * (rdispls[me] + k - nsend)] : &send[(size_t) ncol * k];
    std::copy_n(&rows[(size_t) ncol * r], ncol, to);
  }
  alltoallv(ncol, scounts, sdispls, rcounts, rdispls, send.data(), got.data());
  if (!tags) return;

  std::vector<tagint> sendtags((size_t) ntag * nsend);
  got_tags->resize((size_t) ntag * nrecv);
  for (int k = 0; k < n; k++) {
    tagint *to = k < nsend ? &sendtags[(size_t) ntag * k]
                           : &(*got_tags)[(size_t) ntag * (rdispls[me] + k - nsend)];
    std::copy_n(&(*tags)[(size_t) ntag * order[k]], ntag, to);
  }
  for (int p = 0; p < nprocs; p++) {
    scounts[p] *= ntag;
    sdispls[p] *= ntag;
    rcounts[p] *= ntag;
    rdispls[p] *= ntag;
  }
  MPI_Alltoallv(sendtags.data(), scounts.data(), sdispls.data(), MPI_LMP_TAGINT, got_tags->data(),
                rcounts.data(), rdispls.data(), MPI_LMP_TAGINT, world);
}

/* ----------------------------------------------------------------------
   every rank's home values on every rank (root < 0) or on root only, in cell order
------------------------------------------------------------------------- */

static void collect(MPI_Comm world, int nprocs, int root, int ncol, const std::vector<int> &mine,
                    const std::vector<double> &values, int ncell, std::vector<double> &out)
{
  // rows: the cell index, then its ncol values
  const int width = ncol + 1, n = (int) mine.size();
  std::vector<double> rows((size_t) width * n);
  for (int k = 0; k < n; k++) {
    rows[(size_t) width * k] = mine[k];
    std::copy_n(&values[(size_t) ncol * k], ncol, &rows[(size_t) width * k + 1]);
  }
  const int count = width * n;
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  if (root < 0)
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  else
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, root, world);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  std::vector<double> all(displs.back() + counts.back());
  if (root < 0)
    MPI_Allgatherv(rows.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                   MPI_DOUBLE, world);
  else
    MPI_Gatherv(rows.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                MPI_DOUBLE, root, world);
  out.assign((size_t) ncol * ncell, 0.0);
  for (size_t r = 0; r < all.size(); r += width)
    std::copy_n(&all[r + 1], ncol, &out[(size_t) ncol * (int) all[r]]);
}

void CellRegistry::allgather(int ncol, const std::vector<double> &values,
                             std::vector<double> &out) const
{
  collect(world, comm->nprocs, -1, ncol, mine, values, ncell(), out);
}

void CellRegistry::gather(int ncol, const std::vector<double> &values,
                          std::vector<double> &out) const
{
  collect(world, comm->nprocs, 0, ncol, mine, values, ncell(), out);
}

/* ---------------------------------------------------------------------- */

void CellRegistry::settle(int failed, const std::string &message,
                          const std::vector<std::string> &warnings)
{
  // {lowest failed cell, -(warnings)}: one MPI_MIN
  int flags[2] = {failed, -(int) warnings.size()}, any[2];
  MPI_Allreduce(flags, any, 2, MPI_INT, MPI_MIN, world);
  if (any[1] < 0) {
    std::string text;
    for (const auto &w : warnings) text += w + '\n';
    const int len = (int) text.size();
    std::vector<int> lens(comm->nprocs), displs(comm->nprocs, 0);
    MPI_Gather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, 0, world);
    for (int p = 1; p < comm->nprocs; p++) displs[p] = displs[p - 1] + lens[p - 1];
    std::string all(comm->me == 0 ? displs.back() + lens.back() : 0, '\0');
    MPI_Gatherv(text.data(), len, MPI_CHAR, &all[0], lens.data(), displs.data(), MPI_CHAR, 0,
                world);
    for (size_t at = 0, end; (end = all.find('\n', at)) != std::string::npos; at = end + 1)
      error->warning(FLERR, all.substr(at, end - at));
  }
  if (any[0] >= ncell()) return;
  const int root = homes[any[0]];
  std::string text = comm->me == root ? message : std::string();
  int len = (int) text.size();
  MPI_Bcast(&len, 1, MPI_INT, root, world);
  text.resize(len);
  MPI_Bcast(&text[0], len, MPI_CHAR, root, world);
  error->all(FLERR, text);
}
