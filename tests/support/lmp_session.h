// A LAMMPS instance with the GRANPEN styles, driven command by command, for
// in-process tests (as LAMMPS's own unittest does). Output is silenced
// unless GRANPEN_TEST_VERBOSE is set.
#ifndef GRANPEN_TEST_LMP_SESSION_H
#define GRANPEN_TEST_LMP_SESSION_H

#include "atom.h"
#include "input.h"
#include "lammps.h"
#include "library.h"
#include "style_registry.h"
#include "update.h"

#include <cstdlib>
#include <mpi.h>
#include <string>
#include <vector>

class LmpSession {
 public:
  LmpSession()
  {
    std::vector<const char *> args = {"granpen_test", "-log", "none", "-nocite"};
    if (!std::getenv("GRANPEN_TEST_VERBOSE")) {
      args.push_back("-screen");
      args.push_back("none");
    }
    lmp = new LAMMPS_NS::LAMMPS((int) args.size(), const_cast<char **>(args.data()), MPI_COMM_WORLD);
    granpen::register_styles(lmp);
  }
  ~LmpSession() { delete lmp; }
  LmpSession(const LmpSession &) = delete;
  LmpSession &operator=(const LmpSession &) = delete;

  void cmd(const std::string &line) { lmp->input->one(line); }
  void cmds(const std::vector<std::string> &lines)
  {
    for (auto &l : lines) cmd(l);
  }

  double fix_vector(const char *id, int i)
  {
    auto p = (double *) lammps_extract_fix(lmp, id, LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, i, 0);
    double v = p ? *p : NAN;
    lammps_free(p);
    return v;
  }
  double compute_vector(const char *id, int i)
  {
    auto p = (double *) lammps_extract_compute(lmp, id, LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR);
    return p ? p[i] : NAN;
  }
  double equal(const std::string &expr)
  {
    cmd("variable granpen_tmp equal " + expr);
    auto p = (double *) lammps_extract_variable(lmp, "granpen_tmp", nullptr);
    double v = p ? *p : NAN;
    lammps_free(p);
    return v;
  }
  // per-atom vector of every atom, ordered by atom ID, on every rank
  std::vector<double> gather(const char *name, int count)
  {
    std::vector<double> data((size_t) lmp->atom->natoms * count);
    lammps_gather_atoms(lmp, const_cast<char *>(name), 1, count, data.data());
    return data;
  }
  std::vector<int> gather_int(const char *name, int count)    // an integer per-atom property (type, ...)
  {
    std::vector<int> data((size_t) lmp->atom->natoms * count);
    lammps_gather_atoms(lmp, const_cast<char *>(name), 0, count, data.data());
    return data;
  }
  int rank() const
  {
    int r;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
  }

  LAMMPS_NS::LAMMPS *lmp;
};

#endif
