// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CONVENIENCE_H
#define CGAL_PROGRESSIVE_EMBEDDING_CONVENIENCE_H

/// \file progressive_embedding.h
/// Convenience header: includes the whole public API of the package.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/check_immersion.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/embed_patch.h>
#include <CGAL/Progressive_embedding/triangulate_self_overlapping_polygon_2.h>
#include <CGAL/Progressive_embedding/Constrained_embedding_statistics.h>
#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/cross_parameterization.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_parameterizer_3.h>
#include <CGAL/Progressive_embedding/distortion.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/certified_pipeline.h>
#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>
#include <CGAL/Progressive_embedding/IO/SVG.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_CONVENIENCE_H
