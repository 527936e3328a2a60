// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_VERSION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_VERSION_H

#include <CGAL/license/Surface_mesh_parameterization.h>

/// \file Discrete_lie_flow_version.h
/// The version of the Discrete Lie Flow package, encoded as CGAL encodes its
/// own in `<CGAL/version.h>`. CMake reads `DISCRETE_LIE_FLOW_VERSION` from
/// this file: it is the single place where the version is set.

/// \ingroup PkgDiscreteLieFlowVersion
/// The version as a bare token sequence `major.minor.patch`.
#define DISCRETE_LIE_FLOW_VERSION 1.0.0

/// \ingroup PkgDiscreteLieFlowVersion
/// The version as one number, `1MMmmPBBBB` as `CGAL_VERSION_NR`: major `MM`,
/// minor `mm`, patch `P`, and `BBBB` = 1000 for a release. Compare it with
/// `DISCRETE_LIE_FLOW_VERSION_NUMBER(x, y, z)`.
#define DISCRETE_LIE_FLOW_VERSION_NR 1010001000

/// \ingroup PkgDiscreteLieFlowVersion
/// The version as a string literal, `"1.0.0"`.
#define DISCRETE_LIE_FLOW_VERSION_STR DISCRETE_LIE_FLOW_STR_(DISCRETE_LIE_FLOW_VERSION)

/// \ingroup PkgDiscreteLieFlowVersion
/// The major version.
#define DISCRETE_LIE_FLOW_VERSION_MAJOR (DISCRETE_LIE_FLOW_VERSION_NR / 10000000 % 100)
/// \ingroup PkgDiscreteLieFlowVersion
/// The minor version.
#define DISCRETE_LIE_FLOW_VERSION_MINOR (DISCRETE_LIE_FLOW_VERSION_NR / 100000 % 100)
/// \ingroup PkgDiscreteLieFlowVersion
/// The patch version.
#define DISCRETE_LIE_FLOW_VERSION_PATCH (DISCRETE_LIE_FLOW_VERSION_NR / 10000 % 10)

/// \ingroup PkgDiscreteLieFlowVersion
/// The `DISCRETE_LIE_FLOW_VERSION_NR` of version `x.y.z`, for tests such as
/// `#if DISCRETE_LIE_FLOW_VERSION_NR >= DISCRETE_LIE_FLOW_VERSION_NUMBER(1, 0, 0)`.
#define DISCRETE_LIE_FLOW_VERSION_NUMBER(x, y, z) ((1000001 + 10000 * (x) + 100 * (y) + 10 * (z)) * 1000)

/// \cond SKIP_IN_MANUAL
#define DISCRETE_LIE_FLOW_STR_(X) DISCRETE_LIE_FLOW_STR_STR_(X)
#define DISCRETE_LIE_FLOW_STR_STR_(X) #X
/// \endcond

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_VERSION_H
