!> Raster back ends: libpng (PNG writing) and OSMesa (off-screen OpenGL).
!> The PNG device (plot_png) uses both; these probes report the versions.
module plot_backends
   use, intrinsic :: iso_c_binding, only: c_int, c_ptr, c_null_ptr, c_associated, c_int32_t
   implicit none
   private
   public :: png_version_string, osmesa_available, fp_traps_off, fp_traps_restore

   integer(c_int), parameter :: osmesa_rgba = int(z'1908', c_int)   ! GL_RGBA

   interface
      function png_access_version_number() bind(c, name='png_access_version_number')
         import :: c_int32_t
         integer(c_int32_t) :: png_access_version_number
      end function png_access_version_number
      function osmesa_create_context(format, sharelist) bind(c, name='OSMesaCreateContext')
         import :: c_int, c_ptr
         integer(c_int), value :: format
         type(c_ptr), value :: sharelist
         type(c_ptr) :: osmesa_create_context
      end function osmesa_create_context
      subroutine osmesa_destroy_context(ctx) bind(c, name='OSMesaDestroyContext')
         import :: c_ptr
         type(c_ptr), value :: ctx
      end subroutine osmesa_destroy_context
      function fp_traps_off() bind(c, name='udec_fp_traps_off')
         import :: c_int
         integer(c_int) :: fp_traps_off
      end function fp_traps_off
      subroutine fp_traps_restore(old) bind(c, name='udec_fp_traps_restore')
         import :: c_int
         integer(c_int), value :: old
      end subroutine fp_traps_restore
   end interface

contains

   !> "major.minor.release" of the linked libpng.
   function png_version_string() result(text)
      character(len=:), allocatable :: text
      integer :: v
      character(len=32) :: buf
      v = int(png_access_version_number())
      write (buf, '(i0,".",i0,".",i0)') v/10000, mod(v/100, 100), mod(v, 100)
      text = trim(buf)
   end function png_version_string

   !> True when an OSMesa off-screen context can be created.
   logical function osmesa_available()
      type(c_ptr) :: ctx
      integer(c_int) :: traps
      traps = fp_traps_off()        ! Mesa's own arithmetic must not hit our FP traps
      ctx = osmesa_create_context(osmesa_rgba, c_null_ptr)
      osmesa_available = c_associated(ctx)
      if (osmesa_available) call osmesa_destroy_context(ctx)
      call fp_traps_restore(traps)
   end function osmesa_available

end module plot_backends
