# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/plot/plot_backends.mod"
  "mod/plot/PLOT_BACKENDS.mod"
  "CMakeFiles/udec_plot.dir/plot_backends.mod.stamp"

  "mod/plot/plot_build.mod"
  "mod/plot/PLOT_BUILD.mod"
  "CMakeFiles/udec_plot.dir/plot_build.mod.stamp"

  "mod/plot/plot_device.mod"
  "mod/plot/PLOT_DEVICE.mod"
  "CMakeFiles/udec_plot.dir/plot_device.mod.stamp"

  "mod/plot/plot_factory.mod"
  "mod/plot/PLOT_FACTORY.mod"
  "CMakeFiles/udec_plot.dir/plot_factory.mod.stamp"

  "mod/plot/plot_fluid.mod"
  "mod/plot/PLOT_FLUID.mod"
  "CMakeFiles/udec_plot.dir/plot_fluid.mod.stamp"

  "mod/plot/plot_font.mod"
  "mod/plot/PLOT_FONT.mod"
  "CMakeFiles/udec_plot.dir/plot_font.mod.stamp"

  "mod/plot/plot_history.mod"
  "mod/plot/PLOT_HISTORY.mod"
  "CMakeFiles/udec_plot.dir/plot_history.mod.stamp"

  "mod/plot/plot_layers.mod"
  "mod/plot/PLOT_LAYERS.mod"
  "CMakeFiles/udec_plot.dir/plot_layers.mod.stamp"

  "mod/plot/plot_legend.mod"
  "mod/plot/PLOT_LEGEND.mod"
  "CMakeFiles/udec_plot.dir/plot_legend.mod.stamp"

  "mod/plot/plot_png.mod"
  "mod/plot/PLOT_PNG.mod"
  "CMakeFiles/udec_plot.dir/plot_png.mod.stamp"

  "mod/plot/plot_profiles.mod"
  "mod/plot/PLOT_PROFILES.mod"
  "CMakeFiles/udec_plot.dir/plot_profiles.mod.stamp"

  "mod/plot/plot_ps.mod"
  "mod/plot/PLOT_PS.mod"
  "CMakeFiles/udec_plot.dir/plot_ps.mod.stamp"

  "mod/plot/plot_scene.mod"
  "mod/plot/PLOT_SCENE.mod"
  "CMakeFiles/udec_plot.dir/plot_scene.mod.stamp"

  "mod/plot/plot_thist.mod"
  "mod/plot/PLOT_THIST.mod"
  "CMakeFiles/udec_plot.dir/plot_thist.mod.stamp"

  "mod/plot/plot_zones.mod"
  "mod/plot/PLOT_ZONES.mod"
  "CMakeFiles/udec_plot.dir/plot_zones.mod.stamp"
  )
