/* -*- c++ -*- ----------------------------------------------------------
   cellsph - SPH-DEM plant cells for LAMMPS
   format versions of the package's restart payloads: since version 2 a payload begins with
   -version; files written before versions (version 1) begin with a value >= 0 of the payload
------------------------------------------------------------------------- */

#ifndef LMP_CELL_RESTART_H
#define LMP_CELL_RESTART_H

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cmath>
#include <cstdio>
#include <mpi.h>
#include <string>

namespace CellRestart {

// the format version of a payload whose first value is first
inline int version(double first)
{
  return first < 0.0 ? static_cast<int>(lround(-first)) : 1;
}

// stop (on all ranks) when the file was written by a newer plugin than this one
inline void refuse_newer(LAMMPS_NS::Error *error, const std::string &file, int line,
                         const std::string &style, int version, int current)
{
  if (version > current)
    error->all(file, line,
               "{}: the restart file has format version {}, newer than this plugin's {}: use a "
               "newer cellsph",
               style, version, current);
}

inline MPI_Datatype mpi_type(const double *)
{
  return MPI_DOUBLE;
}

inline MPI_Datatype mpi_type(const int *)
{
  return MPI_INT;
}

// write -version, then n values of each column in turn (per-type coefficients: &array[1])
template <class... T> void write_columns(FILE *fp, int version, int n, const T *...columns)
{
  const double marker = -version;
  fwrite(&marker, sizeof(double), 1, fp);
  (fwrite(columns, sizeof(T), n, fp), ...);
}

// read n values into column on rank 0 and broadcast them
template <class T> void read_column(LAMMPS_NS::LAMMPS *lmp, FILE *fp, int n, T *column)
{
  if (lmp->comm->me == 0)
    LAMMPS_NS::utils::sfread(FLERR, column, sizeof(T), n, fp, nullptr, lmp->error);
  MPI_Bcast(column, n, mpi_type(column), 0, lmp->world);
}

// read what write_columns wrote after the marker: n values of each column in turn
template <class... T> void read_columns(LAMMPS_NS::LAMMPS *lmp, FILE *fp, int n, T *...columns)
{
  (read_column(lmp, fp, n, columns), ...);
}

// read the payload's first value (into first, if given) and return its version; stop (on all
// ranks, with file and line of the caller) when it is newer than current
inline int read_version(LAMMPS_NS::LAMMPS *lmp, FILE *fp, const std::string &file, int line,
                        const std::string &style, int current, double *first = nullptr)
{
  double value = 0.0;
  read_column(lmp, fp, 1, &value);
  const int v = version(value);
  refuse_newer(lmp->error, file, line, style, v, current);
  if (first) *first = value;
  return v;
}

}    // namespace CellRestart

#endif
