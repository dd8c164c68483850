!> The device-independent picture that PLOT builds and COPY writes.
!>
!> A scene is a list of items in page coordinates (origin bottom left, one
!> unit = one pixel of the default PNG): open polylines, closed outlines,
!> filled polygons and text. Items drawn in model (window) coordinates go
!> through the scene's view (`to_page`) and are clipped to the viewport.
!> Layers also add legend entries (text, colour swatches, line-thickness and
!> vector scales) that `plot_legend` lays out in the legend panel.
module plot_scene
   use core_kinds, only: wp, i8
   use core_output, only: fmt_real
   implicit none
   private
   public :: plot_scene_t, plot_item_t, legend_entry_t
   public :: item_polyline, item_polygon, item_fill, item_text
   public :: align_left, align_centre, align_right
   public :: legend_text, legend_swatch, legend_line, legend_arrow, legend_title, legend_bar
   public :: black, grey, light_grey, white, red, blue, green, dark_green, orange, purple
   public :: brown, magenta, cyan, series_colour, material_colour, format_number, nice_number, format_tick

   integer, parameter :: item_polyline = 1, item_polygon = 2, item_fill = 3, item_text = 4
   integer, parameter :: align_left = 0, align_centre = 1, align_right = 2
   integer, parameter :: legend_text = 1, legend_swatch = 2, legend_line = 3, &
                         legend_arrow = 4, legend_title = 5, legend_bar = 6

   !> Named colours (red, green, blue fractions).
   real(wp), parameter :: black(3) = [0.0_wp, 0.0_wp, 0.0_wp], &
      white(3) = [1.0_wp, 1.0_wp, 1.0_wp], &
      grey(3) = [0.45_wp, 0.45_wp, 0.45_wp], light_grey(3) = [0.8_wp, 0.8_wp, 0.8_wp], &
      red(3) = [0.84_wp, 0.1_wp, 0.1_wp], blue(3) = [0.1_wp, 0.3_wp, 0.85_wp], &
      green(3) = [0.15_wp, 0.6_wp, 0.15_wp], dark_green(3) = [0.0_wp, 0.45_wp, 0.3_wp], &
      orange(3) = [0.95_wp, 0.5_wp, 0.0_wp], purple(3) = [0.5_wp, 0.2_wp, 0.7_wp], &
      brown(3) = [0.55_wp, 0.3_wp, 0.1_wp], magenta(3) = [0.85_wp, 0.1_wp, 0.6_wp], &
      cyan(3) = [0.0_wp, 0.6_wp, 0.75_wp]

   !> One drawable item; points are the slice first .. first+count-1.
   type :: plot_item_t
      integer :: kind = item_polyline
      integer :: first = 1, count = 0
      real(wp) :: colour(3) = 0.0_wp
      real(wp) :: width = 1.0_wp          !< line width (page units)
      logical :: clip = .false.           !< clipped to the viewport
      real(wp) :: size = 0.0_wp           !< text cap height (page units)
      integer :: align = align_left       !< text: which end sits at the point
      real(wp) :: angle = 0.0_wp          !< text direction, degrees
      character(len=:), allocatable :: text
   end type plot_item_t

   !> One line of the legend panel.
   type :: legend_entry_t
      integer :: kind = legend_text
      character(len=:), allocatable :: text
      real(wp) :: colour(3) = 0.0_wp
      real(wp) :: width = 1.0_wp          !< legend_line: thickness to show
      real(wp) :: length = 0.0_wp         !< legend_arrow: arrow length (page units)
      !> legend_bar: one band of a colour bar (entries in a row, highest
      !> first, drawn as one continuous bar): `text` labels its upper edge,
      !> `low` its lower edge (written under the last band of the run)
      character(len=:), allocatable :: low
   end type legend_entry_t

   type :: plot_scene_t
      real(wp) :: page_w = 1200.0_wp, page_h = 840.0_wp
      !> Viewport (page) the window maps onto; items with clip stay inside.
      real(wp) :: vx0 = 0.0_wp, vx1 = 1.0_wp, vy0 = 0.0_wp, vy1 = 1.0_wp
      real(wp) :: window(4) = [0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp]   !< xl xu yl yu
      real(wp) :: sx = 1.0_wp, sy = 1.0_wp, ox = 0.0_wp, oy = 0.0_wp   !< page = o + s*world
      logical :: heading_on = .true.      !< heading band and legend panel drawn
      character(len=:), allocatable :: heading
      real(wp) :: time = 0.0_wp
      !> thermal time (RUN), shown beside the mechanical time when positive
      real(wp) :: thermal_time = 0.0_wp
      integer(i8) :: cycle = 0_i8
      character(len=:), allocatable :: what   !< what is plotted ("BLOCKS VELOCITY")
      integer :: nitem = 0
      type(plot_item_t), allocatable :: items(:)
      integer :: npoint = 0
      real(wp), allocatable :: x(:), y(:)
      integer :: nlegend = 0
      type(legend_entry_t), allocatable :: legend(:)
   contains
      procedure :: init => scene_init
      procedure :: set_view => scene_set_view
      procedure :: to_page => scene_to_page
      procedure :: world_length => scene_world_length
      procedure :: polyline => scene_polyline
      procedure :: world_polyline => scene_world_polyline
      procedure :: text => scene_text
      procedure :: arrow => scene_arrow
      procedure :: add_legend => scene_add_legend
   end type plot_scene_t

contains

   !> An empty scene. With `heading_on`, the page has a heading band and a
   !> legend panel left of the square plotting area; without, the page is the
   !> square plotting area alone.
   subroutine scene_init(this, heading_on)
      class(plot_scene_t), intent(out) :: this
      logical, intent(in) :: heading_on
      this%heading_on = heading_on
      if (heading_on) then
         this%page_w = 1200.0_wp; this%page_h = 840.0_wp
         this%vx0 = 420.0_wp; this%vx1 = 1180.0_wp; this%vy0 = 20.0_wp; this%vy1 = 780.0_wp
      else
         this%page_w = 840.0_wp; this%page_h = 840.0_wp
         this%vx0 = 20.0_wp; this%vx1 = 820.0_wp; this%vy0 = 20.0_wp; this%vy1 = 820.0_wp
      end if
      this%heading = ''
      this%what = ''
      allocate (this%items(256), this%x(4096), this%y(4096), this%legend(16))
   end subroutine scene_init

   !> Map `window` (xl xu yl yu) onto the page box [bx0,bx1] x [by0,by1].
   !> With `keep_aspect` one scale serves both axes and the window is centred
   !> in the box; the viewport (clip box) becomes the window's image.
   subroutine scene_set_view(this, window, box, keep_aspect)
      class(plot_scene_t), intent(inout) :: this
      real(wp), intent(in) :: window(4), box(4)
      logical, intent(in) :: keep_aspect
      real(wp) :: s, cx, cy
      this%window = window
      this%sx = (box(2) - box(1))/(window(2) - window(1))
      this%sy = (box(4) - box(3))/(window(4) - window(3))
      if (keep_aspect) then
         s = min(this%sx, this%sy)
         this%sx = s
         this%sy = s
      end if
      cx = 0.5_wp*(box(1) + box(2))
      cy = 0.5_wp*(box(3) + box(4))
      this%ox = cx - this%sx*0.5_wp*(window(1) + window(2))
      this%oy = cy - this%sy*0.5_wp*(window(3) + window(4))
      this%vx0 = this%ox + this%sx*window(1)
      this%vx1 = this%ox + this%sx*window(2)
      this%vy0 = this%oy + this%sy*window(3)
      this%vy1 = this%oy + this%sy*window(4)
   end subroutine scene_set_view

   elemental subroutine scene_to_page(this, wx, wy, px, py)
      class(plot_scene_t), intent(in) :: this
      real(wp), intent(in) :: wx, wy
      real(wp), intent(out) :: px, py
      px = this%ox + this%sx*wx
      py = this%oy + this%sy*wy
   end subroutine scene_to_page

   !> Page length of a model length (x scale).
   pure real(wp) function scene_world_length(this, length) result(p)
      class(plot_scene_t), intent(in) :: this
      real(wp), intent(in) :: length
      p = this%sx*length
   end function scene_world_length

   !> Append an item of `kind` (polyline, polygon, fill) with page points.
   subroutine scene_polyline(this, kind, x, y, colour, width, clip)
      class(plot_scene_t), intent(inout) :: this
      integer, intent(in) :: kind
      real(wp), intent(in) :: x(:), y(:)
      real(wp), intent(in) :: colour(3)
      real(wp), intent(in), optional :: width
      logical, intent(in), optional :: clip
      integer :: n
      n = size(x)
      if (n < 2) return
      call reserve(this, 1, n)
      this%nitem = this%nitem + 1
      associate (it => this%items(this%nitem))
         it%kind = kind
         it%first = this%npoint + 1
         it%count = n
         it%colour = colour
         it%width = 1.0_wp
         if (present(width)) it%width = width
         it%clip = .false.
         if (present(clip)) it%clip = clip
      end associate
      this%x(this%npoint + 1:this%npoint + n) = x
      this%y(this%npoint + 1:this%npoint + n) = y
      this%npoint = this%npoint + n
   end subroutine scene_polyline

   !> As `polyline` with model coordinates, clipped to the viewport.
   subroutine scene_world_polyline(this, kind, x, y, colour, width)
      class(plot_scene_t), intent(inout) :: this
      integer, intent(in) :: kind
      real(wp), intent(in) :: x(:), y(:)
      real(wp), intent(in) :: colour(3)
      real(wp), intent(in), optional :: width
      real(wp) :: px(size(x)), py(size(y))
      call this%to_page(x, y, px, py)
      call this%polyline(kind, px, py, colour, width, clip=.true.)
   end subroutine scene_world_polyline

   !> Text with its baseline at page point (x, y); `size` is the cap height.
   subroutine scene_text(this, text, x, y, size, colour, align, angle, clip)
      class(plot_scene_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      real(wp), intent(in) :: x, y, size
      real(wp), intent(in) :: colour(3)
      integer, intent(in), optional :: align
      real(wp), intent(in), optional :: angle
      logical, intent(in), optional :: clip
      if (len_trim(text) == 0) return
      call reserve(this, 1, 1)
      this%nitem = this%nitem + 1
      associate (it => this%items(this%nitem))
         it%kind = item_text
         it%first = this%npoint + 1
         it%count = 1
         it%colour = colour
         it%size = size
         it%text = trim(text)
         it%align = align_left
         if (present(align)) it%align = align
         it%angle = 0.0_wp
         if (present(angle)) it%angle = angle
         it%clip = .false.
         if (present(clip)) it%clip = clip
         it%width = max(1.0_wp, 0.1_wp*size)
      end associate
      this%npoint = this%npoint + 1
      this%x(this%npoint) = x
      this%y(this%npoint) = y
   end subroutine scene_text

   !> Arrow between page points (x1,y1) -> (x2,y2): a shaft and a filled head
   !> whose size follows the arrow length (at most `head_max`).
   subroutine scene_arrow(this, x1, y1, x2, y2, colour, width, clip, head_max)
      class(plot_scene_t), intent(inout) :: this
      real(wp), intent(in) :: x1, y1, x2, y2
      real(wp), intent(in) :: colour(3)
      real(wp), intent(in) :: width
      logical, intent(in) :: clip
      real(wp), intent(in), optional :: head_max
      real(wp) :: length, ux, uy, h, hw, hmax
      length = hypot(x2 - x1, y2 - y1)
      if (length <= 0.0_wp) return
      hmax = 12.0_wp
      if (present(head_max)) hmax = head_max
      ux = (x2 - x1)/length
      uy = (y2 - y1)/length
      h = min(hmax, 0.35_wp*length)
      hw = 0.4_wp*h
      call this%polyline(item_polyline, [x1, x2 - 0.5_wp*h*ux], [y1, y2 - 0.5_wp*h*uy], &
                         colour, width, clip)
      call this%polyline(item_fill, [x2, x2 - h*ux - hw*uy, x2 - h*ux + hw*uy], &
                         [y2, y2 - h*uy + hw*ux, y2 - h*uy - hw*ux], colour, width, clip)
   end subroutine scene_arrow

   !> Append a legend entry.
   subroutine scene_add_legend(this, kind, text, colour, width, length, low)
      class(plot_scene_t), intent(inout) :: this
      integer, intent(in) :: kind
      character(len=*), intent(in) :: text
      real(wp), intent(in), optional :: colour(3)
      real(wp), intent(in), optional :: width, length
      character(len=*), intent(in), optional :: low
      type(legend_entry_t), allocatable :: t(:)
      if (this%nlegend >= size(this%legend)) then
         allocate (t(2*size(this%legend)))
         t(1:this%nlegend) = this%legend(1:this%nlegend)
         call move_alloc(t, this%legend)
      end if
      this%nlegend = this%nlegend + 1
      associate (e => this%legend(this%nlegend))
         e%kind = kind
         e%text = text
         e%colour = black
         if (present(colour)) e%colour = colour
         e%width = 1.0_wp
         if (present(width)) e%width = width
         e%length = 0.0_wp
         if (present(length)) e%length = length
         e%low = ''
         if (present(low)) e%low = low
      end associate
   end subroutine scene_add_legend

   !> Room for `nitem` more items and `npoint` more points.
   subroutine reserve(this, nitem, npoint)
      class(plot_scene_t), intent(inout) :: this
      integer, intent(in) :: nitem, npoint
      type(plot_item_t), allocatable :: t(:)
      real(wp), allocatable :: r(:)
      integer :: m
      if (this%nitem + nitem > size(this%items)) then
         m = max(2*size(this%items), this%nitem + nitem)
         allocate (t(m))
         t(1:this%nitem) = this%items(1:this%nitem)
         call move_alloc(t, this%items)
      end if
      if (this%npoint + npoint > size(this%x)) then
         m = max(2*size(this%x), this%npoint + npoint)
         allocate (r(m))
         r(1:this%npoint) = this%x(1:this%npoint)
         call move_alloc(r, this%x)
         allocate (r(m))
         r(1:this%npoint) = this%y(1:this%npoint)
         call move_alloc(r, this%y)
      end if
   end subroutine reserve

   !> Colour of data series k (history curves): distinct, dark enough for
   !> thin lines on white.
   pure function series_colour(k) result(c)
      integer, intent(in) :: k
      real(wp) :: c(3)
      real(wp), parameter :: table(3, 8) = reshape([blue, red, green, orange, purple, brown, &
                                                    magenta, cyan], [3, 8])
      c = table(:, modulo(k - 1, 8) + 1)
   end function series_colour

   !> Fill colour of material m: light tints that block outlines and
   !> vectors stay visible on, distinct from their neighbours in the list.
   pure function material_colour(m) result(c)
      integer, intent(in) :: m
      real(wp) :: c(3)
      real(wp), parameter :: table(3, 10) = reshape([ &
         0.62_wp, 0.78_wp, 0.95_wp, 0.98_wp, 0.76_wp, 0.52_wp, 0.66_wp, 0.88_wp, 0.60_wp, &
         0.95_wp, 0.62_wp, 0.66_wp, 0.80_wp, 0.70_wp, 0.92_wp, 0.85_wp, 0.75_wp, 0.60_wp, &
         0.98_wp, 0.92_wp, 0.50_wp, 0.60_wp, 0.90_wp, 0.90_wp, 0.80_wp, 0.80_wp, 0.80_wp, &
         0.95_wp, 0.70_wp, 0.90_wp], [3, 10])
      c = table(:, modulo(m - 1, 10) + 1)
   end function material_colour

   !> A number as legends print it: "0", or 4 significant digits in
   !> E notation ("1.234E-02").
   function format_number(v) result(text)
      real(wp), intent(in) :: v
      character(len=:), allocatable :: text
      text = '0'
      if (v /= 0.0_wp) text = trim(adjustl(fmt_real(v, 11, 3)))
   end function format_number

   !> The 1, 2 or 5 times a power of ten nearest below |v| (v /= 0), for
   !> scale bars and axis steps.
   pure real(wp) function nice_number(v) result(r)
      real(wp), intent(in) :: v
      real(wp) :: p, f
      if (v == 0.0_wp) then
         r = 0.0_wp
         return
      end if
      p = 10.0_wp**floor(log10(abs(v)))
      f = abs(v)/p
      if (f >= 5.0_wp) then
         r = 5.0_wp*p
      else if (f >= 2.0_wp) then
         r = 2.0_wp*p
      else
         r = p
      end if
   end function nice_number

   !> Tick label: plain decimals for moderate values, E notation otherwise.
   function format_tick(v) result(text)
      real(wp), intent(in) :: v
      character(len=:), allocatable :: text
      character(len=32) :: buf
      if (v == 0.0_wp) then
         text = '0'
      else if (abs(v) >= 1.0e-3_wp .and. abs(v) < 1.0e5_wp) then
         write (buf, '(f0.4)') v
         text = trim(buf)
         do while (text(len(text):len(text)) == '0')
            text = text(1:len(text) - 1)
         end do
         if (text(len(text):len(text)) == '.') text = text(1:len(text) - 1)
         if (text(1:1) == '.') text = '0'//text
         ! a one-character label ('5') has no second character to compare
         ! (valgrind: a read past its end, issue 20)
         if (len(text) >= 2) then
            if (text(1:2) == '-.') text = '-0'//text(2:)
         end if
      else
         text = trim(adjustl(fmt_real(v, 10, 2)))
      end if
   end function format_tick

end module plot_scene
