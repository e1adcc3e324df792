/* Compiled with each compile-only variant of src/ (tests/compat/CMakeLists.txt): fails to
   compile unless the variant's settings reached the compiler, so a variant that silently
   fell back to the default build cannot pass. GRANPEN_EXPECT_BIGBIG and
   GRANPEN_EXPECT_STUBS say what the variant claims. */

#include "lmptype.h"

#include <mpi.h>

#ifdef GRANPEN_EXPECT_BIGBIG
static_assert(sizeof(LAMMPS_NS::tagint) == 8 && sizeof(LAMMPS_NS::imageint) == 8,
              "LAMMPS_BIGBIG did not take effect: tagint or imageint is not 64-bit");
#else
static_assert(sizeof(LAMMPS_NS::tagint) == 4 && sizeof(LAMMPS_NS::bigint) == 8,
              "not LAMMPS_SMALLBIG: tagint is not 32-bit or bigint not 64-bit");
#endif

#if defined(GRANPEN_EXPECT_STUBS) && !defined(MPI_STUBS)
#error "the STUBS variant compiled against a real MPI's mpi.h"
#endif
#if !defined(GRANPEN_EXPECT_STUBS) && defined(MPI_STUBS)
#error "an MPI variant compiled against LAMMPS's STUBS mpi.h"
#endif

int granpen_variant_probe() { return static_cast<int>(sizeof(LAMMPS_NS::tagint)); }
