// The LAMMPS data file cellgen writes (README.md "Output: LAMMPS data file").
#include "datafile.h"

#include <algorithm>
#include <stdexcept>

namespace cellgen {

namespace {

  // Per-type mass of the Masses section: that of cell 1 (CellAtoms holds every atom's own mass).
  // Walls only (--nfluid 0): no atom has type 1, which gets the wall mass as a placeholder.
  double typeMass(const System &sys, ParticleType type)
  {
    auto first = std::find_if(sys.particles.begin(), sys.particles.end(),
                              [type](const Particle &p) { return p.type == type; });
    if (first == sys.particles.end())
      first = std::find_if(sys.particles.begin(), sys.particles.end(),
                           [](const Particle &p) { return p.type == kWall; });
    return first->mass;
  }

  void writeHeader(std::FILE *f, const System &sys, const std::string &comment, const DataExtras &x)
  {
    const size_t ndihedrals = x.dihedrals.size();
    std::fprintf(f, "%s\n\n", comment.c_str());
    std::fprintf(f, "%zu atoms\n%zu bonds\n%zu angles\n", sys.particles.size(),
                 sys.bonds.size() + x.junctions.size(), sys.triangles.size());
    if (ndihedrals > 0) std::fprintf(f, "%zu dihedrals\n", ndihedrals);
    std::fprintf(f, "2 atom types\n%d bond types\n1 angle types\n", x.bondTypes);
    if (ndihedrals > 0) std::fprintf(f, "1 dihedral types\n");
    std::fprintf(f, "\n");
    const char *names[3] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d)
      std::fprintf(f, "%.15g %.15g %slo %shi\n", sys.lo[d], sys.hi[d], names[d], names[d]);
    std::fprintf(f, "\nMasses\n\n1 %.15g\n2 %.15g\n", typeMass(sys, kFluid), typeMass(sys, kWall));
  }

  // Dihedrals section (--dihedrals): one per wall edge, a b c d with (a, b, c) and (d, c, b) the
  // outward triangles sharing the edge b-c (dihedral_style cell/bending)
  void writeDihedrals(std::FILE *f, const std::vector<Quad> &dihedrals)
  {
    std::fprintf(f, "\nDihedrals\n\n");
    for (size_t i = 0; i < dihedrals.size(); ++i) {
      const Quad &q = dihedrals[i];
      std::fprintf(f, "%zu 1 %d %d %d %d\n", i + 1, q[0] + 1, q[1] + 1, q[2] + 1, q[3] + 1);
    }
  }

  // Dihedrals, if any, come before CellAtoms: LAMMPS 29 Sep 2021 reads no section after a fix
  // section
  void writeSections(std::FILE *f, const System &sys, const DataExtras &x)
  {
    std::fprintf(f, "\nAtoms # %s\n\n", x.dihedrals.empty() ? "angle" : "molecular");
    for (size_t i = 0; i < sys.particles.size(); ++i) {
      const Particle &p = sys.particles[i];
      std::fprintf(f, "%zu %d %d %.15g %.15g %.15g\n", i + 1, p.molecule, static_cast<int>(p.type),
                   p.x[0], p.x[1], p.x[2]);
    }
    std::fprintf(f, "\nBonds\n\n");
    size_t id = 0;
    for (const Edge &e : sys.bonds) std::fprintf(f, "%zu 1 %d %d\n", ++id, e[0] + 1, e[1] + 1);
    for (const Edge &e : x.junctions) std::fprintf(f, "%zu 2 %d %d\n", ++id, e[0] + 1, e[1] + 1);
    std::fprintf(f, "\nAngles\n\n");
    for (size_t i = 0; i < sys.triangles.size(); ++i) {
      const Tri &t = sys.triangles[i];
      std::fprintf(f, "%zu 1 %d %d %d\n", i + 1, t[0] + 1, t[1] + 1, t[2] + 1);
    }
    if (!x.dihedrals.empty()) writeDihedrals(f, x.dihedrals);
    // area shares of the wall bonds only (junction bonds carry no wall area)
    const std::vector<double> aref = bondAreaShares(sys);
    std::fprintf(f, "\nCellAtoms # rmass xref(3) aref\n\n");
    for (size_t i = 0; i < sys.particles.size(); ++i) {
      const Particle &p = sys.particles[i];
      std::fprintf(f, "%zu %.15g %.15g %.15g %.15g %.15g\n", i + 1, p.mass, p.x[0], p.x[1], p.x[2],
                   aref[i]);
    }
  }

}    // namespace

File openOut(const std::string &path)
{
  File f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) throw std::runtime_error("cannot open " + path + " for writing");
  return f;
}

void closeOut(File &f, const std::string &path)
{
  if (std::ferror(f.get()) || std::fclose(f.release()) != 0)
    throw std::runtime_error("error writing " + path);
}

void writeData(const std::string &path, const System &sys, const std::string &comment,
               const DataExtras &extras)
{
  File f = openOut(path);
  writeHeader(f.get(), sys, comment, extras);
  writeSections(f.get(), sys, extras);
  closeOut(f, path);
}

}    // namespace cellgen
