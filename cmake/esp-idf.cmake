# SPDX-License-Identifier: MIT
# fixtrace as an ESP-IDF component (idf_component.yml): the top-level
# CMakeLists.txt includes this file when ESP_PLATFORM is set. Every
# core/*/*.c, with each core folder public, so the application includes
# "rt_render.h". The core's configuration is rt_config.h's defaults; a
# fixtrace_conf.h on the include path, or definitions added to the build
# (idf_build_set_property(COMPILE_DEFINITIONS ...)), change them for the
# core and the application alike.
file(GLOB fixtrace_sources ${CMAKE_CURRENT_LIST_DIR}/../core/*/*.c)
idf_component_register(
    SRCS ${fixtrace_sources}
    INCLUDE_DIRS core/fx core/scene core/shapes core/parse core/accel core/trace
                 core/frame)
# Optimised whatever the project's level: the renderer is several times
# slower without, and larger.
target_compile_options(${COMPONENT_LIB} PRIVATE -O2 -ffunction-sections
    -fdata-sections)
