!> Raster back ends: libpng (PNG writing) and OSMesa (off-screen OpenGL).
!> The PNG device (plot_png) uses both; these probes report the versions.
!> OSMesa is not linked: plot_gl.c opens it with dlopen at the first PNG
!> (osmesa_load), so a run without PNG plots does not map it (nor the
!> libLLVM it pulls in).
module plot_backends
   use, intrinsic :: iso_c_binding, only: c_int, c_ptr, c_associated, c_int32_t, c_char, &
                                          c_null_char
   implicit none
   private
   public :: png_version_string, osmesa_available, fp_traps_off, fp_traps_restore
   public :: osmesa_load, osmesa_loaded

   integer(c_int), parameter :: osmesa_rgba = int(z'1908', c_int)   ! GL_RGBA

   interface
      function png_access_version_number() bind(c, name='png_access_version_number')
         import :: c_int32_t
         integer(c_int32_t) :: png_access_version_number
      end function png_access_version_number
      function gl_load(message, message_len) bind(c, name='udec_gl_load')
         import :: c_int, c_char
         character(kind=c_char), intent(inout) :: message(*)
         integer(c_int), value :: message_len
         integer(c_int) :: gl_load
      end function gl_load
      function gl_loaded() bind(c, name='udec_gl_loaded')
         import :: c_int
         integer(c_int) :: gl_loaded
      end function gl_loaded
      function osmesa_create(format, depth, stencil, accum) bind(c, name='udec_osmesa_create')
         import :: c_int, c_ptr
         integer(c_int), value :: format, depth, stencil, accum
         type(c_ptr) :: osmesa_create
      end function osmesa_create
      subroutine osmesa_destroy(ctx) bind(c, name='udec_osmesa_destroy')
         import :: c_ptr
         type(c_ptr), value :: ctx
      end subroutine osmesa_destroy
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

   !> Open the OSMesa library if not yet open (once per process). `ok` false:
   !> `message` says why (the names tried and the loader's reason). The
   !> libraries' initialisers run with floating-point traps off, as every
   !> call into Mesa does (Debug builds trap).
   subroutine osmesa_load(message, ok)
      character(len=*), intent(out) :: message
      logical, intent(out) :: ok
      character(kind=c_char) :: buf(400)
      integer :: i
      integer(c_int) :: traps
      buf = c_null_char
      traps = fp_traps_off()
      ok = gl_load(buf, int(size(buf), c_int)) == 0
      call fp_traps_restore(traps)
      message = ''
      do i = 1, min(size(buf), len(message))
         if (buf(i) == c_null_char) exit
         message(i:i) = buf(i)
      end do
   end subroutine osmesa_load

   !> True once the OSMesa library is loaded in this process.
   logical function osmesa_loaded()
      osmesa_loaded = gl_loaded() /= 0
   end function osmesa_loaded

   !> True when the OSMesa library loads and an off-screen context can be
   !> created; `message` (optional) is the reason when it cannot be loaded.
   logical function osmesa_available(message)
      character(len=*), intent(out), optional :: message
      character(len=400) :: why
      type(c_ptr) :: ctx
      integer(c_int) :: traps
      logical :: ok
      call osmesa_load(why, ok)
      if (present(message)) message = why
      osmesa_available = .false.
      if (.not. ok) return
      traps = fp_traps_off()        ! Mesa's own arithmetic must not hit our FP traps
      ctx = osmesa_create(osmesa_rgba, 0_c_int, 0_c_int, 0_c_int)
      osmesa_available = c_associated(ctx)
      if (osmesa_available) call osmesa_destroy(ctx)
      call fp_traps_restore(traps)
   end function osmesa_available

end module plot_backends
