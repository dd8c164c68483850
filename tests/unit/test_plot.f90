!> PLOT / COPY / WINDOW: the scene a command builds (positions, scales,
!> legend), the devices and their factory, and the command errors. Model
!> velocities, displacements, contact state and histories are set directly
!> (the cycle that fills them is tested elsewhere). File contents (valid
!> PostScript, decodable PNG) are checked by tests/scripts/plot_files.py.
program test_plot
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use testing, only: check, check_close, check_equal, check_string, testing_finish, delete_file
   use commands_session, only: session_t, session_init, session_execute_line
   use model_history, only: history_add, history_record, hist_yvel, hist_xvel
   use contact_joint_law, only: state_slip, state_tension, state_fractured
   use plot_scene, only: plot_scene_t, item_fill, item_polyline, item_text, legend_arrow, &
                         legend_line, format_tick
   use plot_font, only: font_text_width
   use plot_layers, only: plot_contact_slip, plot_contact_tension, plot_contact_fractured, plot_layer_names
   use plot_build, only: plot_auto_window
   use plot_device, only: plot_device_t
   use plot_factory, only: plot_device_names, plot_device_create, plot_device_for_file
   implicit none
   type(session_t) :: s
   type(error_t), allocatable :: error
   class(plot_device_t), allocatable :: device
   real(wp) :: w(4), px, py, tipx, tipy, width_max
   integer :: k, nfill, errors_before, c, nthick, i
   integer(ip) :: ib

   ! ---- font and factory -------------------------------------------------
   ! 'A' spans grid x 0..4: at cap height 6 one unit is 1, so width 4 exactly
   call check_close(font_text_width('A', 6.0_wp), 4.0_wp, 0.0_wp, 'font: width of A')
   ! 'AB': A advances 6, B is 4 wide -> 10
   call check_close(font_text_width('AB', 6.0_wp), 10.0_wp, 0.0_wp, 'font: width of AB')
   do k = 1, size(plot_device_names)
      call plot_device_create(trim(plot_device_names(k)), device, error)
      call check(.not. allocated(error), 'factory builds '//trim(plot_device_names(k)))
      if (allocated(device)) call check_string(device%name(), trim(plot_device_names(k)), &
                                               'device name')
   end do
   call plot_device_create('HPGL', device, error)
   call check(allocated(error), 'factory: unknown device is an error')
   if (allocated(error)) call check(index(error%message, 'PS, PNG') > 0, &
                                    'factory error names the known devices')
   ! one-character tick labels: formatting read past their end (issue 20,
   ! valgrind; -fcheck=bounds in the Debug build stops on it)
   call check_string(format_tick(5.0_wp), '5', 'tick label 5')
   call check_string(format_tick(-0.5_wp), '-0.5', 'tick label -0.5')
   call check_string(format_tick(-2.0_wp), '-2', 'tick label -2')
   call check_string(format_tick(0.25_wp), '0.25', 'tick label 0.25')
   call check_string(plot_device_for_file('BLOCKS.PLT', 'PS'), 'PS', '.PLT follows the route')
   call check_string(plot_device_for_file('PLT', 'PNG'), 'PNG', 'no extension: route')
   call check_string(plot_device_for_file('a.eps', 'PNG'), 'PS', '.eps is PostScript')
   call check_string(plot_device_for_file('dir.x/a.Png', 'PS'), 'PNG', '.png is PNG')
   call check_string(plot_device_for_file('dir.ps/PLT', 'PNG'), 'PNG', 'a dot in a folder')
   call check_equal(plot_contact_slip, state_slip, 'slip bit agrees with the joint law')
   call check_equal(plot_contact_tension, state_tension, 'tension bit agrees')
   call check_equal(plot_contact_fractured, state_fractured, 'fracture bit agrees')

   ! ---- the tutorial geometry (manual Section 2.1) ----------------------
   call session_init(s, error)
   s%out%screen = .false.
   call run('COPY')
   call check_equal(s%nerrors, 1, 'COPY before any PLOT is an error')
   call run('PLOT BLOCKS')
   call check_equal(s%nerrors, 2, 'PLOT before BLOCK is an error')
   call run('BLOCK (0,0) (0,20) (20,20) (20,0)')
   call run('SPLIT (0,2) (20,8)')
   call run('SPLIT (5,3) (5,20)')
   call run('SPLIT (5,12) (20,18)')
   errors_before = s%nerrors

   ! default window: square, 10% larger than the 20 x 20 model (5% a side)
   w = plot_auto_window(s%model)
   call check_close(w(1), -1.0_wp, 1.0e-12_wp, 'auto window xl')
   call check_close(w(2), 21.0_wp, 1.0e-12_wp, 'auto window xu')
   call check_close(w(3), -1.0_wp, 1.0e-12_wp, 'auto window yl')
   call check_close(w(4), 21.0_wp, 1.0e-12_wp, 'auto window yu')

   ! every layer of this module draws without error and shows in the legend
   do k = 1, size(plot_layer_names)
      call run('PLOT '//trim(plot_layer_names(k)))
      call check(index(s%plot%scene%what, trim(plot_layer_names(k))) > 0, &
                 'layer listed in the legend: '//trim(plot_layer_names(k)))
   end do
   call check_equal(s%nerrors, errors_before, 'all model layers plot')

   ! the picture keeps the aspect ratio: equal x and y scales
   call run('PLOT BLOCKS')
   call check_close(s%plot%scene%sx, s%plot%scene%sy, 1.0e-12_wp, 'equal scales')
   ! a non-square window is letter-boxed, not distorted, and clips
   call run('WINDOW 0 20 5 15')
   call run('PLOT BLOCKS')
   call check_close(s%plot%scene%sx, s%plot%scene%sy, 1.0e-12_wp, 'equal scales, 20 x 10')
   call check_close(s%plot%scene%vx1 - s%plot%scene%vx0, &
                    2.0_wp*(s%plot%scene%vy1 - s%plot%scene%vy0), 1.0e-12_wp, &
                    'viewport is 2:1 like the window')
   call run('WINDOW AUTO')
   call check(s%plot%window_auto, 'WINDOW AUTO restores the default')
   call run('WINDOW 5 1 0 1')
   call check_equal(s%nerrors, errors_before + 1, 'WINDOW with xu < xl is an error')
   call check(s%plot%window_auto, 'a rejected WINDOW changes nothing')

   ! ---- velocity vectors: the largest is 5% of the window (manual 4.6) --
   ib = 3
   s%model%geometry%blocks%vx(ib) = 0.3_wp
   s%model%geometry%blocks%vy(ib) = -0.4_wp
   call run('PLOT BLOCKS VELOCITY')
   nfill = 0
   do k = 1, s%plot%scene%nitem
      if (s%plot%scene%items(k)%kind == item_fill .and. s%plot%scene%items(k)%clip) then
         nfill = nfill + 1
         tipx = s%plot%scene%x(s%plot%scene%items(k)%first)
         tipy = s%plot%scene%y(s%plot%scene%items(k)%first)
      end if
   end do
   call check_equal(nfill, 1, 'one arrow head: one moving block')
   ! |v| = 0.5, window 22 -> arrow length 0.05*22 = 1.1 along (0.6, -0.8)
   call s%plot%scene%to_page(s%model%geometry%blocks%xc(ib) + 1.1_wp*0.6_wp, &
                             s%model%geometry%blocks%yc(ib) - 1.1_wp*0.8_wp, px, py)
   call check_close(tipx, px, 1.0e-9_wp, 'arrow tip x (5% of window)')
   call check_close(tipy, py, 1.0e-9_wp, 'arrow tip y')
   call check(has_legend_text('maximum = 5.000E-01'), 'legend shows the maximum velocity')
   call check(has_legend_kind(legend_arrow), 'legend has a vector scale')
   ! with <sc> = 10 the arrow is 10 * 0.5 = 5 model units long
   call run('PLOT VEL 10')
   do k = 1, s%plot%scene%nitem
      if (s%plot%scene%items(k)%kind == item_fill .and. s%plot%scene%items(k)%clip) then
         tipx = s%plot%scene%x(s%plot%scene%items(k)%first)
      end if
   end do
   call s%plot%scene%to_page(s%model%geometry%blocks%xc(ib) + 5.0_wp*0.6_wp, 0.0_wp, px, py)
   call check_close(tipx, px, 1.0e-9_wp, 'arrow tip with scale 10')
   call run('PLOT VEL 0')
   call check_equal(s%nerrors, errors_before + 2, 'a zero scale is an error')

   ! ---- displacement vectors at the corners ------------------------------
   c = s%model%geometry%blocks%first_corner(ib)
   s%model%geometry%corners%ux(c) = 0.01_wp
   call run('PLOT DISP')
   call check(has_legend_text('maximum = 1.000E-02'), 'DISP maximum in the legend')

   ! ---- joint shear as line thickness; slip and opening ------------------
   associate (st => s%model%geometry%contacts%state)
      st%us(1) = 2.0e-3_wp
      st%us(2) = -1.0e-3_wp
      st%flags(1) = state_slip
      st%flags(2) = state_tension
      st%un(3) = -5.0e-4_wp
   end associate
   call run('PLOT SHEAR')
   width_max = 0.0_wp
   nthick = 0
   do k = 1, s%plot%scene%nitem
      if (s%plot%scene%items(k)%kind == item_polyline .and. s%plot%scene%items(k)%clip) then
         width_max = max(width_max, s%plot%scene%items(k)%width)
         nthick = nthick + 1
      end if
   end do
   call check_equal(nthick, 2, 'two contacts with shear displacement')
   ! the largest |us| gets the reference thickness 8 page units
   call check_close(width_max, 8.0_wp, 1.0e-12_wp, 'largest shear = reference thickness')
   call check(has_legend_kind(legend_line), 'thickness scale in the legend')
   call run('PLOT SHEAR 4e-3')
   width_max = 0.0_wp
   do k = 1, s%plot%scene%nitem
      if (s%plot%scene%items(k)%kind == item_polyline .and. s%plot%scene%items(k)%clip) &
         width_max = max(width_max, s%plot%scene%items(k)%width)
   end do
   call check_close(width_max, 4.0_wp, 1.0e-12_wp, 'SHEAR sc: 2e-3 / 4e-3 * 8')
   call run('PLOT SLIP')
   call check(has_legend_text('at slip (1)') .and. has_legend_text('open (1)'), &
              'SLIP counts slipping and open contacts')
   ! FRACTURES: contacts with the JCONS 5 fracture flag (one of them also open)
   s%model%geometry%contacts%state%flags(2) = ior(state_tension, state_fractured)
   call run('PLOT FRACTURES')
   call check(has_legend_text('fractured joints, JCONS 5 (1)'), 'FRACTURES counts flagged contacts')
   call run('PLOT CLOSURE')
   call check(has_legend_text('maximum = 5.000E-04'), 'CLOSURE maximum')

   ! ---- legend: heading, time, cycle, window -----------------------------
   s%model%heading = 'MY TITLE'
   s%model%mech%time = 1.5_wp
   s%model%mech%step = 120
   call run('PLOT BLOCKS')
   ! issue 24: one title line with the heading, the cycle and the time
   call check(has_text('MY TITLE   cycle 120   time 1.500E+00 s'), &
              'title line: heading, cycle and time')
   call check(has_text('time   1.500E+00'), 'time in the legend')
   call check(has_text('cycle  120'), 'cycle in the legend')
   call check(has_text('  x: -1.000E+00 to 2.100E+01'), 'window in the legend')
   call run('PLOT BLOCKS NOHEADING')
   call check(.not. has_text('MY TITLE'), 'NOHEADING: no caption')
   call check_close(s%plot%scene%page_w, s%plot%scene%page_h, 0.0_wp, 'NOHEADING: square page')

   ! ---- histories ---------------------------------------------------------
   call run('PLOT HISTORY 1')
   call check_equal(s%nerrors, errors_before + 2, 'no histories yet: a warning, not an error')
   call check(s%plot%has_scene .and. has_legend_text('(no histories defined)'), &
              'no histories: an empty graph that COPY can write')
   call history_add(s%model%hist, hist_yvel, 3_ip, 10.0_wp, 20.0_wp, 5.0_wp, 20.0_wp)
   call history_add(s%model%hist, hist_xvel, 3_ip, 10.0_wp, 20.0_wp, 5.0_wp, 20.0_wp)
   do i = 1, 50
      call history_record(s%model%hist, 0.01_wp*i, int(10*i, ip), &
                          [-1.0e-3_wp*i, 2.0e-3_wp*i])
   end do
   call run('PLOT HISTORY 1 2')
   call check(has_legend_text(' 1 YVEL at (5.000E+00, 2.000E+01) (m/s)'), 'history 1 in the legend')
   call check_equal(curve_points(), 50, 'a curve of 50 samples')
   ! first sample (t = 0.01, v = -1e-3) sits where the view puts it
   call s%plot%scene%to_page(0.01_wp, -1.0e-3_wp, px, py)
   call check_close(curve_x1(), px, 1.0e-9_wp, 'first history point x')
   call check_close(curve_y1(), py, 1.0e-9_wp, 'first history point y')
   call run('PLOT AB 2 YREV XWINDOW 0 0.2 HISTORY 1')
   ! abscissa = history 2 (2e-3 at sample 1); ordinate = -(-1e-3)
   call s%plot%scene%to_page(2.0e-3_wp, 1.0e-3_wp, px, py)
   call check_close(curve_x1(), px, 1.0e-9_wp, 'AB 2: first point x is history 2')
   call check_close(curve_y1(), py, 1.0e-9_wp, 'YREV: first point y reversed')
   call check_close(s%plot%scene%window(2), 0.2_wp, 1.0e-12_wp, 'XWINDOW sets the x range')
   call run('PLOT HISTORY 3')
   call check_equal(s%nerrors, errors_before + 3, 'undefined history is an error')
   call run('PLOT HISTORY 1 BLOCKS')
   call check_equal(s%nerrors, errors_before + 4, 'history and model layers do not mix')

   ! ---- COPY writes both formats -----------------------------------------
   call run('PLOT BLOCKS VEL')
   call run('COPY test_plot_out.ps')
   call run('COPY test_plot_out.png')
   call check(s%plot%copied, 'COPY marks the picture written')
   call check_equal(s%nerrors, errors_before + 4, 'COPY succeeded')
   call check(png_size('test_plot_out.png', 1200, 840), 'PNG is 1200 x 840')
   call check(first_line('test_plot_out.ps') == '%!PS-Adobe-3.0 EPSF-3.0', 'PostScript header')
   call delete_file('test_plot_out.ps')
   call delete_file('test_plot_out.png')
   call testing_finish()

contains

   subroutine run(line)
      character(len=*), intent(in) :: line
      call session_execute_line(s, line, 1)
   end subroutine run

   logical function has_text(text)
      character(len=*), intent(in) :: text
      integer :: j
      has_text = .false.
      do j = 1, s%plot%scene%nitem
         if (s%plot%scene%items(j)%kind == item_text) then
            if (s%plot%scene%items(j)%text == text) has_text = .true.
         end if
      end do
   end function has_text

   logical function has_legend_text(text)
      character(len=*), intent(in) :: text
      integer :: j
      has_legend_text = .false.
      do j = 1, s%plot%scene%nlegend
         if (s%plot%scene%legend(j)%text == text) has_legend_text = .true.
      end do
   end function has_legend_text

   logical function has_legend_kind(kind)
      integer, intent(in) :: kind
      integer :: j
      has_legend_kind = .false.
      do j = 1, s%plot%scene%nlegend
         if (s%plot%scene%legend(j)%kind == kind) has_legend_kind = .true.
      end do
   end function has_legend_kind

   !> The first clipped polyline of the scene (the first history curve).
   integer function curve_item()
      integer :: j
      curve_item = 0
      do j = 1, s%plot%scene%nitem
         if (s%plot%scene%items(j)%kind == item_polyline .and. s%plot%scene%items(j)%clip) then
            curve_item = j
            return
         end if
      end do
   end function curve_item

   integer function curve_points()
      curve_points = 0
      if (curve_item() > 0) curve_points = s%plot%scene%items(curve_item())%count
   end function curve_points

   real(wp) function curve_x1()
      curve_x1 = -1.0_wp
      if (curve_item() > 0) curve_x1 = s%plot%scene%x(s%plot%scene%items(curve_item())%first)
   end function curve_x1

   real(wp) function curve_y1()
      curve_y1 = -1.0_wp
      if (curve_item() > 0) curve_y1 = s%plot%scene%y(s%plot%scene%items(curve_item())%first)
   end function curve_y1

   !> PNG signature and IHDR width/height (big-endian at bytes 17-24).
   logical function png_size(path, width, height)
      character(len=*), intent(in) :: path
      integer, intent(in) :: width, height
      character(len=24) :: head
      integer :: u, ios
      png_size = .false.
      open (newunit=u, file=path, access='stream', form='unformatted', status='old', &
            action='read', iostat=ios)
      if (ios /= 0) return
      read (u, iostat=ios) head
      close (u)
      if (ios /= 0) return
      png_size = head(2:4) == 'PNG' .and. head(13:16) == 'IHDR' .and. &
                 be32(head(17:20)) == width .and. be32(head(21:24)) == height
   end function png_size

   integer function be32(b)
      character(len=4), intent(in) :: b
      integer :: j
      be32 = 0
      do j = 1, 4
         be32 = be32*256 + iachar(b(j:j))
      end do
   end function be32

   function first_line(path) result(text)
      character(len=*), intent(in) :: path
      character(len=80) :: text
      integer :: u, ios
      text = ''
      open (newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) return
      read (u, '(a)', iostat=ios) text
      close (u)
   end function first_line

end program test_plot
