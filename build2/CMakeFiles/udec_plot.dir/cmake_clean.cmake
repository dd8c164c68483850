file(REMOVE_RECURSE
  "CMakeFiles/udec_plot.dir/src/plot/plot_backends.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_build.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_device.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_factory.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_fenv.c.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_fenv.c.o.d"
  "CMakeFiles/udec_plot.dir/src/plot/plot_fluid.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_font.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_history.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_layers.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_legend.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_png.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_png_write.c.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_png_write.c.o.d"
  "CMakeFiles/udec_plot.dir/src/plot/plot_profiles.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_ps.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_scene.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_thist.f90.o"
  "CMakeFiles/udec_plot.dir/src/plot/plot_zones.f90.o"
  "libudec_plot.a"
  "libudec_plot.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C Fortran)
  include(CMakeFiles/udec_plot.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
