# Spack recipe for granpen: the GRANPEN plugin for a Spack-built LAMMPS (+plugin), the decks
# and the post-processor. Not built here (no Spack on the development machine):
# tests/install/recipes.sh checks that cmake_args below are the -D options of
# packaging/conda/build.sh and runs that route against Debian's LAMMPS source tree, installs,
# moves the prefix and loads the installed plugin into a LAMMPS built with PLUGIN
# (docs/install.md). Use: `spack repo add packaging/spack`... or copy granpen/ into a repo.
#
# The plugin is compiled against the LAMMPS source of the exact release that loads it: each
# lammps version below has its own source resource, used only with that version.

from spack.package import *


class Granpen(CMakePackage):
    """Constant-speed rod penetration into granular beds: the LAMMPS package GRANPEN as a
    plugin (fix rod/drive, computes rod/drag, bed/surface, flow/azimuthal, momentum/vbin,
    create_rod, restore_contact_history), its input decks and the granpen-cli post-processor."""

    homepage = "https://github.com/granpen/granpen"
    git = "https://github.com/granpen/granpen.git"

    license("GPL-2.0-only")

    version("main", branch="main")

    variant("postprocessor", default=True, description="Build granpen-cli and granpen-demo")

    depends_on("cxx", type="build")
    depends_on("cmake@3.16:", type="build")
    depends_on("mpi")
    depends_on("voropp")
    # the styles are compiled with LAMMPS_SMALLBIG, LAMMPS's default integer sizes
    depends_on("lammps+plugin+granular+voronoi+lib+mpi lammps_sizes=smallbig")
    depends_on("eigen@3.3:", when="+postprocessor")
    depends_on("zlib-api", when="+postprocessor")
    depends_on("cli11", when="+postprocessor")
    depends_on("nlohmann-json@3:", when="+postprocessor")
    depends_on("gnuplot", type="run", when="+postprocessor")

    # LAMMPS's src/ of the release the plugin is built for (Spack's lammps installs only its
    # public headers); the URLs and checksums are those of Spack's own lammps package
    lammps_sources = {
        "20250722.3": (
            "stable_22Jul2025_update3",
            "07f487cc33fc8f2ec4a449b7bce570e52b5a46608075e0276d26e0e232511bef",
        ),
        "20210929.3": (
            "stable_29Sep2021_update3",
            "e4c274f0dc5fdedc43f2b365156653d1105197a116ff2bafe893523cdb22532e",
        ),
    }
    for lammps_version, (release, checksum) in lammps_sources.items():
        resource(
            name="lammps-src",
            url=f"https://github.com/lammps/lammps/archive/{release}.tar.gz",
            sha256=checksum,
            destination="",
            placement="lammps-src",
            when=f"^lammps@{lammps_version}",
        )
    depends_on("lammps@" + ",".join(lammps_sources))

    def cmake_args(self):
        # CMAKE_BUILD_TYPE (variant build_type, Release) and CMAKE_INSTALL_PREFIX are Spack's own
        return [
            self.define("LAMMPS_SOURCE_DIR", join_path(self.stage.source_path, "lammps-src")),
            self.define("CMAKE_DISABLE_FIND_PACKAGE_LAMMPS", True),
            self.define("GRANPEN_TESTS", False),
            self.define_from_variant("GRANPEN_POSTPROCESSOR", "postprocessor"),
        ]

    def setup_run_environment(self, env):
        # plugin.lmp loads ${granpen_prefix}/lib/granpen/granpenplugin.so
        env.set("GRANPEN_PREFIX", self.prefix)
