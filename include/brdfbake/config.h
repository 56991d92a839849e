// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The model families this build of the library contains (CMake option
// BRDFBAKE_MODELS, e.g. -DBRDFBAKE_MODELS="ggx;beckmann"). GGX is always
// built: the tests' independent reference rule (tests/reference/) maps
// every model through the GGX visible-normal disk. std needs beckmann (its gamma = inf limit). The
// scalar reference headers are header-only and always available; what a
// family's absence removes is its SIMD kernels and its entry in the
// run-time registry (eval, bake, grids, stability, scenes).

#ifndef BRDFBAKE_CONFIG_H_
#define BRDFBAKE_CONFIG_H_

#ifndef BRDFBAKE_WITH_BECKMANN
#define BRDFBAKE_WITH_BECKMANN 1
#endif
#ifndef BRDFBAKE_WITH_STD
#define BRDFBAKE_WITH_STD 1
#endif
#ifndef BRDFBAKE_WITH_ELLIPSOID
#define BRDFBAKE_WITH_ELLIPSOID 1
#endif
#ifndef BRDFBAKE_WITH_SEL
#define BRDFBAKE_WITH_SEL 1
#endif

#ifndef BRDFBAKE_WITH_CHARLIE
#define BRDFBAKE_WITH_CHARLIE 1
#endif
#ifndef BRDFBAKE_WITH_DISNEY
#define BRDFBAKE_WITH_DISNEY 1
#endif
// The rough dielectric BSDF (models/dielectric.h): its kernels and
// DielectricBsdfBatch (batch.h). Its Beckmann variant needs beckmann.
#ifndef BRDFBAKE_WITH_GLASS
#define BRDFBAKE_WITH_GLASS 1
#endif

#if BRDFBAKE_WITH_STD && !BRDFBAKE_WITH_BECKMANN
#error "the std family needs beckmann (BRDFBAKE_MODELS)"
#endif

#endif  // BRDFBAKE_CONFIG_H_
