!> PNG device: the scene rendered off-screen by OSMesa (legacy OpenGL into
!> memory) at twice the page resolution, averaged down 2 x 2 (anti-aliased
!> edges), and written with libpng. One page unit is one pixel.
!>
!> Lines are drawn as quads with round joins (as PostScript's round joins),
!> filled polygons with the stencil-buffer parity trick (any simple or
!> non-convex polygon), text with the stroke font of plot_font. Every call
!> into Mesa runs with floating-point traps off (Debug builds trap).
module plot_png
   use, intrinsic :: iso_c_binding, only: c_int, c_ptr, c_null_ptr, c_associated, c_double, &
                                          c_int8_t, c_char, c_null_char, c_loc
   use core_constants, only: pi
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   use plot_scene, only: plot_scene_t, item_polyline, item_polygon, item_fill, item_text
   use plot_font, only: font_strokes, font_text_width
   use plot_device, only: plot_device_t
   use plot_backends, only: fp_traps_off, fp_traps_restore, osmesa_load
   implicit none
   private
   public :: png_device_t, png_supersample

   !> Rendering resolution / output resolution.
   integer, parameter :: png_supersample = 2

   integer(c_int), parameter :: gl_rgba = int(z'1908', c_int)
   integer(c_int), parameter :: gl_unsigned_byte = int(z'1401', c_int)
   integer(c_int), parameter :: gl_triangles = 4, gl_triangle_fan = 6

   type, extends(plot_device_t) :: png_device_t
   contains
      procedure :: write => png_write
   end type png_device_t

   interface
      !> plot_gl.c: OSMesa's context calls through the library it loaded
      !> (plot_backends' osmesa_load first).
      function osmesa_create(format, depth, stencil, accum) bind(c, name='udec_osmesa_create')
         import :: c_int, c_ptr
         integer(c_int), value :: format, depth, stencil, accum
         type(c_ptr) :: osmesa_create
      end function osmesa_create
      function osmesa_make_current(ctx, buffer, type, width, height) &
         bind(c, name='udec_osmesa_make_current')
         import :: c_ptr, c_int
         type(c_ptr), value :: ctx, buffer
         integer(c_int), value :: type, width, height
         integer(c_int) :: osmesa_make_current
      end function osmesa_make_current
      subroutine osmesa_destroy(ctx) bind(c, name='udec_osmesa_destroy')
         import :: c_ptr
         type(c_ptr), value :: ctx
      end subroutine osmesa_destroy
      !> plot_gl.c: the page set-up, the start of an item (clipping and
      !> colour) and the passes of a stencil fill (1 mark, 2 paint, 0 off).
      subroutine gl_page(pw, ph, page_w, page_h, sx, sy, sw, sh) bind(c, name='udec_gl_page')
         import :: c_int, c_double
         integer(c_int), value :: pw, ph, sx, sy, sw, sh
         real(c_double), value :: page_w, page_h
      end subroutine gl_page
      subroutine gl_item(clip, r, g, b) bind(c, name='udec_gl_item')
         import :: c_int, c_double
         integer(c_int), value :: clip
         real(c_double), value :: r, g, b
      end subroutine gl_item
      subroutine gl_stencil(pass) bind(c, name='udec_gl_stencil')
         import :: c_int
         integer(c_int), value :: pass
      end subroutine gl_stencil
      subroutine gl_vertex2d(x, y) bind(c, name='udec_gl_vertex2d')
         import :: c_double
         real(c_double), value :: x, y
      end subroutine gl_vertex2d
      subroutine gl_begin(mode) bind(c, name='udec_gl_begin')
         import :: c_int
         integer(c_int), value :: mode
      end subroutine gl_begin
      subroutine gl_end() bind(c, name='udec_gl_end')
      end subroutine gl_end
      subroutine gl_finish() bind(c, name='udec_gl_finish')
      end subroutine gl_finish
      function png_write_rgb(path, width, height, rgb, message, message_len) &
         bind(c, name='udec_png_write_rgb')
         import :: c_char, c_int, c_int8_t
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: width, height
         integer(c_int8_t), intent(in) :: rgb(*)
         character(kind=c_char), intent(inout) :: message(*)
         integer(c_int), value :: message_len
         integer(c_int) :: png_write_rgb
      end function png_write_rgb
   end interface

contains

   subroutine png_write(this, scene, path, error)
      class(png_device_t), intent(in) :: this
      type(plot_scene_t), intent(in) :: scene
      character(len=*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer(c_int8_t), allocatable, target :: buffer(:, :, :)
      integer(c_int8_t), allocatable :: rgb(:, :, :)
      character(kind=c_char) :: message(200)
      character(len=400) :: text
      integer :: w, h, ss, i, j, k, di, dj, acc
      integer(c_int) :: traps
      logical :: ok
      ss = png_supersample
      w = nint(scene%page_w)
      h = nint(scene%page_h)
      call osmesa_load(text, ok)
      if (.not. ok) then
         call set_error(error, 'COPY: cannot make the PNG file '''//path//"': "//trim(text))
         return
      end if
      allocate (buffer(4, w*ss, h*ss), rgb(3, w, h))
      traps = fp_traps_off()
      call render(scene, buffer, ss, ok)
      call fp_traps_restore(traps)
      if (.not. ok) then
         call set_error(error, 'COPY: cannot create the OSMesa off-screen context for '// &
                        this%name()//" file '"//path//"'")
         return
      end if
      ! average ss x ss samples; OpenGL rows run bottom-up, PNG rows top-down
      do j = 1, h
         do i = 1, w
            do k = 1, 3
               acc = 0
               do dj = 1, ss
                  do di = 1, ss
                     acc = acc + iand(int(buffer(k, (i - 1)*ss + di, (h - j)*ss + dj)), 255)
                  end do
               end do
               acc = (acc + ss*ss/2)/(ss*ss)
               rgb(k, i, j) = int(merge(acc - 256, acc, acc > 127), c_int8_t)
            end do
         end do
      end do
      message = c_null_char
      if (png_write_rgb(trim(path)//c_null_char, int(w, c_int), int(h, c_int), rgb, message, &
                        int(size(message), c_int)) /= 0) then
         text = ''
         do i = 1, size(message)
            if (message(i) == c_null_char) exit
            text(i:i) = message(i)
         end do
         call set_error(error, "COPY: cannot write the PNG file '"//path//"': "//trim(text))
      end if
   end subroutine png_write

   !> Draw the scene into `buffer` (RGBA, rows bottom-up, ss pixels per unit).
   subroutine render(scene, buffer, ss, ok)
      type(plot_scene_t), intent(in) :: scene
      integer(c_int8_t), intent(inout), target :: buffer(:, :, :)
      integer, intent(in) :: ss
      logical, intent(out) :: ok
      type(c_ptr) :: ctx
      integer(c_int) :: pw, ph
      integer :: k
      pw = int(size(buffer, 2), c_int)
      ph = int(size(buffer, 3), c_int)
      ctx = osmesa_create(gl_rgba, 0_c_int, 8_c_int, 0_c_int)
      ok = c_associated(ctx)
      if (.not. ok) return
      if (osmesa_make_current(ctx, c_loc(buffer), gl_unsigned_byte, pw, ph) == 0) then
         call osmesa_destroy(ctx)
         ok = .false.
         return
      end if
      call gl_page(pw, ph, real(scene%page_w, c_double), real(scene%page_h, c_double), &
                   int(floor(scene%vx0*ss), c_int), int(floor(scene%vy0*ss), c_int), &
                   int(ceiling((scene%vx1 - scene%vx0)*ss), c_int), &
                   int(ceiling((scene%vy1 - scene%vy0)*ss), c_int))
      do k = 1, scene%nitem
         associate (it => scene%items(k))
            call gl_item(merge(1_c_int, 0_c_int, it%clip), real(it%colour(1), c_double), &
                         real(it%colour(2), c_double), real(it%colour(3), c_double))
            select case (it%kind)
            case (item_polyline, item_polygon)
               call stroke(scene%x(it%first:it%first + it%count - 1), &
                           scene%y(it%first:it%first + it%count - 1), &
                           it%kind == item_polygon, it%width, ss)
            case (item_fill)
               call fill(scene%x(it%first:it%first + it%count - 1), &
                         scene%y(it%first:it%first + it%count - 1))
            case (item_text)
               call text(it%text, scene%x(it%first), scene%y(it%first), it%size, it%align, &
                         it%angle, it%width, ss)
            end select
         end associate
      end do
      call gl_finish()
      ! release the binding first: a context destroyed while current keeps
      ! its framebuffer referenced (valgrind: lost at every PNG, issue 20)
      if (osmesa_make_current(c_null_ptr, c_null_ptr, gl_unsigned_byte, 0_c_int, 0_c_int) == 0) &
         continue
      call osmesa_destroy(ctx)
   end subroutine render

   !> A polyline (closed when `closed`) of width `width` page units: one quad
   !> per segment and, when the line is wider than a pixel or two, a disc at
   !> every vertex (round joins and caps).
   subroutine stroke(x, y, closed, width, ss)
      real(wp), intent(in) :: x(:), y(:)
      logical, intent(in) :: closed
      real(wp), intent(in) :: width
      integer, intent(in) :: ss
      real(wp) :: hw, dx, dy, len, nx, ny
      integer :: i, j, n, nseg
      n = size(x)
      hw = 0.5_wp*max(width, 1.0_wp/real(ss, wp))
      nseg = n - 1
      if (closed) nseg = n
      call gl_begin(gl_triangles)
      do i = 1, nseg
         j = modulo(i, n) + 1
         dx = x(j) - x(i)
         dy = y(j) - y(i)
         len = hypot(dx, dy)
         if (len <= 0.0_wp) cycle
         nx = -dy/len*hw
         ny = dx/len*hw
         call vertex(x(i) + nx, y(i) + ny)
         call vertex(x(j) + nx, y(j) + ny)
         call vertex(x(j) - nx, y(j) - ny)
         call vertex(x(i) + nx, y(i) + ny)
         call vertex(x(j) - nx, y(j) - ny)
         call vertex(x(i) - nx, y(i) - ny)
      end do
      call gl_end()
      if (hw*real(ss, wp) >= 1.0_wp) then
         do i = 1, n
            call disc(x(i), y(i), hw)
         end do
      end if
   end subroutine stroke

   subroutine disc(x, y, r)
      real(wp), intent(in) :: x, y, r
      integer :: k
      integer, parameter :: nside = 12
      real(wp) :: a
      call gl_begin(gl_triangle_fan)
      call vertex(x, y)
      do k = 0, nside
         a = 2.0_wp*pi*real(k, wp)/real(nside, wp)
         call vertex(x + r*cos(a), y + r*sin(a))
      end do
      call gl_end()
   end subroutine disc

   !> Fill any simple polygon: a triangle fan toggles the stencil parity,
   !> then the pixels of odd parity get the colour (and the stencil is
   !> cleared again by the same pass).
   subroutine fill(x, y)
      real(wp), intent(in) :: x(:), y(:)
      call gl_stencil(1_c_int)
      call fan(x, y)
      call gl_stencil(2_c_int)
      call fan(x, y)
      call gl_stencil(0_c_int)
   contains
      subroutine fan(x, y)
         real(wp), intent(in) :: x(:), y(:)
         integer :: i
         call gl_begin(gl_triangle_fan)
         do i = 1, size(x)
            call vertex(x(i), y(i))
         end do
         call gl_end()
      end subroutine fan
   end subroutine fill

   !> Text in the stroke font; `align` 0/1/2 puts the left end, the centre
   !> or the right end at (x, y).
   subroutine text(string, x, y, size, align, angle, width, ss)
      character(len=*), intent(in) :: string
      real(wp), intent(in) :: x, y, size, angle, width
      integer, intent(in) :: align, ss
      real(wp), allocatable :: sx(:), sy(:)
      integer, allocatable :: first(:)
      integer :: nstroke, k
      real(wp) :: shift, x0, y0, a
      a = angle*pi/180.0_wp
      shift = 0.5_wp*real(align, wp)*font_text_width(string, size)
      x0 = x - shift*cos(a)
      y0 = y - shift*sin(a)
      call font_strokes(string, x0, y0, size, angle, sx, sy, first, nstroke)
      do k = 1, nstroke
         if (first(k + 1) - first(k) >= 2) &
            call stroke(sx(first(k):first(k + 1) - 1), sy(first(k):first(k + 1) - 1), &
                        .false., width, ss)
      end do
   end subroutine text

   subroutine vertex(x, y)
      real(wp), intent(in) :: x, y
      call gl_vertex2d(real(x, c_double), real(y, c_double))
   end subroutine vertex

end module plot_png
