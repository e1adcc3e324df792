/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: granpen developers
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANPEN package: geometry of a rod built from overlapping spheres.
   Pure C++ (no LAMMPS types), so it is unit-tested on its own.
------------------------------------------------------------------------- */

#ifndef LMP_ROD_GEOMETRY_H
#define LMP_ROD_GEOMETRY_H

#include <vector>

namespace granpen {

struct RodSpec {
  double diameter = 2.0;    // outer diameter D: sphere surfaces reach radius D/2
  double length = 6.0;      // from the tip (lowest sphere bottom) to the top sphere top
  double sphere = 0.4;      // diameter of each sphere
  double spacing = 0.2;     // distance between rings and between neighbours in a ring
  bool filled = false;      // false: hollow shell closed by a bottom disc; true: solid
};

// Sphere centre relative to the rod: x, y from the axis, z above the tip; layer 0 is the tip
// (the bottom disc and the shell ring that closes it), layers 1, 2, ... the shaft above it.
struct RodSphere {
  double x, y, z;
  int layer;
};

// Number of spheres on a ring of radius r at the given spacing (1 at r = 0).
int ring_count(double r, double spacing);

// Radii of the rings in one disc layer, from the axis out, ending just inside rshell.
std::vector<double> disc_radii(double rshell, double spacing);

// A rod of more spheres than this is refused (a mistyped spacing or diameter would otherwise
// allocate without bound): the paper's rod of D = 2 cm is about 1200, a filled 10 cm rod
// of 0.2 cm spheres about 2e5.
constexpr double MAX_ROD_SPHERES = 1.0e7;

// The number of spheres build_rod would make, without making them (in double, so that any
// spec gives a finite count). Throws std::invalid_argument as build_rod does.
double rod_sphere_count(const RodSpec &spec);

// Sphere centres of the rod. Shell rings sit at radius D/2 - sphere/2, every
// `spacing` in z from z = sphere/2, alternate rings rotated by half a spacing.
// The shell is closed by a disc (rings at 0, spacing, 2 spacing, ...) in the
// lowest layer, or in every layer when filled. Throws std::invalid_argument
// for a spec that cannot be built, or of more than MAX_ROD_SPHERES spheres.
std::vector<RodSphere> build_rod(const RodSpec &spec);

}    // namespace granpen

#endif
