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
#include "granpen_compat.h"
#include "help_styles.h"
#include "style_registry.h"

#include <cstdio>
#include <cstdlib>
#include <cerrno>
#include <cstring>
#include <dlfcn.h>
#include <mpi.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

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

namespace {

bool asks_for_help(int argc, char **argv)
{
  for (int i = 1; i < argc; ++i)
    if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "-help")) return true;
  return false;
}

// LAMMPS prints its -h text from the style lists it was compiled with and exits inside its
// constructor, before the package's styles can be registered. So a child process prints it
// into a pipe and this one adds the GRANPEN styles to it. Returns the exit status, or -1
// when the child could not be made (then LAMMPS's own text is printed as it is).
int help_with_package_styles(char **argv)
{
  int fd[2];
  if (pipe(fd) != 0) return -1;
  const pid_t child = fork();
  if (child < 0) {
    close(fd[0]);
    close(fd[1]);
    return -1;
  }
  if (child == 0) {
    close(fd[0]);
    if (dup2(fd[1], STDOUT_FILENO) < 0) _exit(1);
    close(fd[1]);
    return -2;    // the child goes on as lmp_granpen -h
  }
  close(fd[1]);
  std::string help;
  char buf[65536];
  ssize_t n;
  while ((n = read(fd[0], buf, sizeof(buf))) > 0 || (n < 0 && errno == EINTR))
    if (n > 0) help.append(buf, static_cast<size_t>(n));
  close(fd[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {}
  granpen::HelpStyles styles;
  granpen::visit_styles([&](granpen::StyleKind kind, const char *name, void *) {
    (kind == granpen::StyleKind::Fix       ? styles.fixes
     : kind == granpen::StyleKind::Compute ? styles.computes
                                           : styles.commands)
        .push_back(name);
  });
  const std::string out = granpen::add_styles_to_help(help, "GRANPEN", styles);
  if (fwrite(out.data(), 1, out.size(), stdout) != out.size() || fflush(stdout) != 0) return 1;
  (void) argv;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

}    // namespace

int main(int argc, char **argv)
{
  if (asks_for_help(argc, argv)) {
    const int rc = help_with_package_styles(argv);
    if (rc >= 0) return rc;    // the parent: done; the child (-2) and a failed fork go on
  }
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
    MPI_Abort(gp::abort_universe(ae), 1);
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
