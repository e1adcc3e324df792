/* ----------------------------------------------------------------------
   lmp_granpen: Debian's LAMMPS (liblammps) with the GRANPEN styles added.
   Behaves as lmp does (same command line, same exit codes): it is LAMMPS's
   main() with one extra call that registers the package's styles before
   the input is read.
------------------------------------------------------------------------- */

#include "accelerator_kokkos.h"
#include "exceptions.h"
#include "input.h"
#include "lammps.h"
#include "lmppython.h"
#include "style_registry.h"

#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>
#include <mpi.h>

using namespace LAMMPS_NS;

// The `clear` command rebuilds LAMMPS's style maps and so would drop the package's
// styles. Input::clear() ends with lmp->post_create(), called through liblammps's PLT,
// so this executable interposes that one function: it runs liblammps's own and then
// registers the styles again. (lmp_granpen is linked with its symbols exported.)
void LAMMPS::post_create()
{
  using PostCreate = void (*)(LAMMPS *);
  static auto original = (PostCreate) dlsym(RTLD_NEXT, "_ZN9LAMMPS_NS6LAMMPS11post_createEv");
  if (!original) {
    fprintf(stderr, "lmp_granpen: cannot find LAMMPS::post_create in liblammps: %s\n", dlerror());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  original(this);
  granpen::register_styles(this);
}

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  MPI_Comm lammps_comm = MPI_COMM_WORLD;

  // LAMMPS throws when built with exceptions, and exits by itself when not
  try {
    auto lammps = new LAMMPS(argc, argv, lammps_comm);
    granpen::register_styles(lammps);
    lammps->input->file();
    delete lammps;
  } catch (LAMMPSAbortException &ae) {
    KokkosLMP::finalize();
    Python::finalize();
    MPI_Abort(ae.universe, 1);
  } catch (LAMMPSException &e) {
    KokkosLMP::finalize();
    Python::finalize();
    MPI_Barrier(lammps_comm);
    MPI_Finalize();
    exit(1);
  } catch (fmt::format_error &fe) {
    fprintf(stderr, "fmt::format_error: %s\n", fe.what());
    KokkosLMP::finalize();
    Python::finalize();
    MPI_Abort(MPI_COMM_WORLD, 1);
    exit(1);
  }
  KokkosLMP::finalize();
  Python::finalize();
  MPI_Barrier(lammps_comm);
  MPI_Finalize();
  return 0;
}
