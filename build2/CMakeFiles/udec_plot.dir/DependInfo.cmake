
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  "Fortran"
  )
# The set of files for implicit dependencies of each language:
set(CMAKE_DEPENDS_CHECK_Fortran
  "/work/wt-lead/src/plot/plot_backends.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_backends.f90.o"
  "/work/wt-lead/src/plot/plot_build.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_build.f90.o"
  "/work/wt-lead/src/plot/plot_device.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_device.f90.o"
  "/work/wt-lead/src/plot/plot_factory.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_factory.f90.o"
  "/work/wt-lead/src/plot/plot_fluid.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_fluid.f90.o"
  "/work/wt-lead/src/plot/plot_font.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_font.f90.o"
  "/work/wt-lead/src/plot/plot_history.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_history.f90.o"
  "/work/wt-lead/src/plot/plot_layers.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_layers.f90.o"
  "/work/wt-lead/src/plot/plot_legend.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_legend.f90.o"
  "/work/wt-lead/src/plot/plot_png.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_png.f90.o"
  "/work/wt-lead/src/plot/plot_profiles.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_profiles.f90.o"
  "/work/wt-lead/src/plot/plot_ps.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_ps.f90.o"
  "/work/wt-lead/src/plot/plot_scene.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_scene.f90.o"
  "/work/wt-lead/src/plot/plot_thist.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_thist.f90.o"
  "/work/wt-lead/src/plot/plot_zones.f90" "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/src/plot/plot_zones.f90.o"
  )
set(CMAKE_Fortran_COMPILER_ID "GNU")
set(CMAKE_Fortran_SUBMODULE_SEP "@")
set(CMAKE_Fortran_SUBMODULE_EXT ".smod")

# The include file search paths:
set(CMAKE_Fortran_TARGET_INCLUDE_PATH
  "mod/plot"
  "mod/model"
  "mod/core"
  "/usr/include/editline"
  "/usr/include"
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/wt-lead/src/plot/plot_fenv.c" "CMakeFiles/udec_plot.dir/src/plot/plot_fenv.c.o" "gcc" "CMakeFiles/udec_plot.dir/src/plot/plot_fenv.c.o.d"
  "/work/wt-lead/src/plot/plot_png_write.c" "CMakeFiles/udec_plot.dir/src/plot/plot_png_write.c.o" "gcc" "CMakeFiles/udec_plot.dir/src/plot/plot_png_write.c.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/wt-lead/build2/CMakeFiles/udec_model.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_core.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "/work/wt-lead/build2/mod/plot")
