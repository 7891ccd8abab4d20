# The numerical core's dependencies (Debian packages, DESIGN.md), shared by
# the main build and the ParaView plugin's.
find_package(embree 3 REQUIRED)
find_package(TBB REQUIRED)
find_package(glm REQUIRED)
find_package(OpenEXR 3 REQUIRED)
find_package(Eigen3 REQUIRED NO_MODULE)
find_package(nlohmann_json 3 REQUIRED)
# CGAL 5 is header-only; exact constructions need GMP and MPFR.
find_package(CGAL 5 REQUIRED)
# nanoflann: the k-d trees of the meshless point hierarchy (header-only).
find_package(nanoflann REQUIRED)
# SLEEF: vectorised atan2 for the contour sums of many edges at one point
# (Common/Atan2Batch.h); Debian ships no CMake config, only pkg-config's.
find_package(PkgConfig REQUIRED)
pkg_check_modules(SLEEF REQUIRED IMPORTED_TARGET sleef)
