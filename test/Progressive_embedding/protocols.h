// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef PROGRESSIVE_EMBEDDING_TEST_PROTOCOLS_H
#define PROGRESSIVE_EMBEDDING_TEST_PROTOCOLS_H

// The data protocols of the tests: the deep stacked triangulation, grid disks, the Tutte-failure
// protocol on closed genus-0 meshes (remove one face, pin its three vertices) and its wider cut.
// `pe` and the benchmarks run them too, so they are library helpers; the tests include them here.

#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>

#endif
