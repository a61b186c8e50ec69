/* SPDX-License-Identifier: MIT */
/*
 * fixtrace_version.h: the version of fixtrace, the one place it is written.
 * The CLI prints it (`fixtrace --version`), CMakeLists.txt reads it for the
 * package version, and tests/suite_package.sh checks that every packaging
 * manifest (library.json, library.properties, idf_component.yml) says the
 * same. Semantic versioning: a minor release may add to the API, a patch
 * release changes none of it.
 */
#ifndef FIXTRACE_VERSION_H
#define FIXTRACE_VERSION_H

#define FIXTRACE_VERSION_MAJOR 0
#define FIXTRACE_VERSION_MINOR 2
#define FIXTRACE_VERSION_PATCH 0

/* One number for #if tests: 10000 * major + 100 * minor + patch. */
#define FIXTRACE_VERSION                                                      \
    (FIXTRACE_VERSION_MAJOR * 10000 + FIXTRACE_VERSION_MINOR * 100 +          \
     FIXTRACE_VERSION_PATCH)

#define FIXTRACE_VERSION_STR_(x) #x
#define FIXTRACE_VERSION_XSTR_(x) FIXTRACE_VERSION_STR_(x)
/* "major.minor.patch", made from the three numbers above. */
#define FIXTRACE_VERSION_STRING                                               \
    FIXTRACE_VERSION_XSTR_(FIXTRACE_VERSION_MAJOR) "."                        \
    FIXTRACE_VERSION_XSTR_(FIXTRACE_VERSION_MINOR) "."                        \
    FIXTRACE_VERSION_XSTR_(FIXTRACE_VERSION_PATCH)

#endif
