/* mpi_collectives: an LD_PRELOAD library (PMPI) that counts the collectives a LAMMPS run
   makes and the time spent in them, by calling site, so that bench/mpi_scaling.sh can say
   how many collectives each GRANPEN style makes per step and what share of a step they take.
   Build: mpicc -O2 -shared -fPIC bench/mpi_collectives.c -o mpi_collectives.so -ldl
   Run:   MPI_COLLECTIVES_OUT=FILE mpirun -np 2 -x LD_PRELOAD=./mpi_collectives.so lmp ...
   Rank 0 writes FILE at MPI_Finalize: one line per calling site,
     name count seconds object offset
   where offset is the return address relative to the object's load base (for addr2line). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

#define MAX_SITES 4096
typedef struct { void *ret; const char *name; long count; double seconds; } Site;
static Site sites[MAX_SITES];
static int nsites = 0;

static Site *site_of(void *ret, const char *name)
{
  for (int i = 0; i < nsites; i++)
    if (sites[i].ret == ret && sites[i].name == name) return &sites[i];
  if (nsites == MAX_SITES) return NULL;    /* table full: not counted (reported below) */
  sites[nsites].ret = ret; sites[nsites].name = name;
  return &sites[nsites++];
}

#define TALLY(NAME, CALL)                                         \
  void *ret = __builtin_return_address(0);                        \
  double t0 = PMPI_Wtime();                                       \
  int rc = CALL;                                                  \
  Site *s = site_of(ret, NAME);                                   \
  if (s) { s->count++; s->seconds += PMPI_Wtime() - t0; }         \
  return rc;

int MPI_Allreduce(const void *a, void *b, int n, MPI_Datatype t, MPI_Op op, MPI_Comm c)
{ TALLY("MPI_Allreduce", PMPI_Allreduce(a, b, n, t, op, c)) }
int MPI_Reduce(const void *a, void *b, int n, MPI_Datatype t, MPI_Op op, int root, MPI_Comm c)
{ TALLY("MPI_Reduce", PMPI_Reduce(a, b, n, t, op, root, c)) }
int MPI_Bcast(void *a, int n, MPI_Datatype t, int root, MPI_Comm c)
{ TALLY("MPI_Bcast", PMPI_Bcast(a, n, t, root, c)) }
int MPI_Allgather(const void *a, int na, MPI_Datatype ta, void *b, int nb, MPI_Datatype tb, MPI_Comm c)
{ TALLY("MPI_Allgather", PMPI_Allgather(a, na, ta, b, nb, tb, c)) }
int MPI_Barrier(MPI_Comm c)
{ TALLY("MPI_Barrier", PMPI_Barrier(c)) }
int MPI_Scan(const void *a, void *b, int n, MPI_Datatype t, MPI_Op op, MPI_Comm c)
{ TALLY("MPI_Scan", PMPI_Scan(a, b, n, t, op, c)) }

int MPI_Finalize(void)
{
  int rank = 0;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const char *path = getenv("MPI_COLLECTIVES_OUT");
  if (rank == 0 && path) {
    FILE *f = fopen(path, "w");
    if (f) {
      for (int i = 0; i < nsites; i++) {
        Dl_info info;
        const char *obj = "?";
        unsigned long off = (unsigned long) sites[i].ret;
        if (dladdr(sites[i].ret, &info) && info.dli_fname) {
          obj = info.dli_fname;
          off = (unsigned long) ((char *) sites[i].ret - (char *) info.dli_fbase);
        }
        fprintf(f, "%s %ld %.9g %s 0x%lx\n", sites[i].name, sites[i].count, sites[i].seconds, obj, off);
      }
      if (nsites == MAX_SITES) fprintf(f, "# site table full: later sites not counted\n");
      if (fclose(f) != 0) fprintf(stderr, "mpi_collectives: could not write %s\n", path);
    } else {
      fprintf(stderr, "mpi_collectives: could not open %s\n", path);
    }
  }
  return PMPI_Finalize();
}
