!> PLOT HISTORY n1 n2 ..: time histories (manual Section 4.6) as curves on
!> axes, with the supplements AB n (history n on the abscissa instead of
!> time), XREV / YREV (sign reversed), XWINDOW / YWINDOW (axis ranges).
module plot_history
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   use model_history, only: history_t, hist_keyword, hist_unit, history_first, hist_ndis, &
                            hist_sdis, &
                            hist_nstr, hist_sstr, hist_srat, hist_bfx, hist_bfy, hist_bfm, &
                            hist_unbal, &
                            hist_damp, hist_xhis, hist_yhis, hist_none
   use plot_scene, only: plot_scene_t, item_polyline, item_polygon, legend_text, &
                         legend_line, legend_title, black, grey, light_grey, series_colour, &
                         format_number, format_tick, nice_number, align_centre, align_right
   use plot_font, only: font_text_width
   use core_output, only: itoa
   implicit none
   private
   public :: history_request_t, plot_history_graph, history_label, widen_range

   !> What the HISTORY keyword and its supplements ask for.
   type :: history_request_t
      integer :: n = 0
      integer, allocatable :: ids(:)
      integer :: abscissa = 0              !< AB n (0: time)
      logical :: xrev = .false., yrev = .false.
      logical :: has_xwin = .false., has_ywin = .false.
      real(wp) :: xwin(2) = 0.0_wp, ywin(2) = 0.0_wp
   end type history_request_t

contains

   !> "YVEL at (10, 20)" for history k taken at a point, "NSTR contact 4" /
   !> "BFX block 2" for one taken at an entity, the name alone otherwise
   !> (UNBAL, DAMP, XHIS, YHIS have no place).
   function history_label(h, k) result(text)
      type(history_t), intent(in) :: h
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      character(len=16) :: id
      write (id, '(i0)') h%entity(k)
      select case (h%kind(k))
      case (hist_ndis, hist_sdis, hist_nstr, hist_sstr, hist_srat)
         text = trim(hist_keyword(h%kind(k)))//' contact '//trim(id)
      case (hist_bfx, hist_bfy, hist_bfm)
         text = trim(hist_keyword(h%kind(k)))//' block '//trim(id)
      case (hist_unbal, hist_damp, hist_xhis, hist_yhis, hist_none)
         text = trim(hist_keyword(h%kind(k)))
      case default
         text = trim(hist_keyword(h%kind(k)))//' at ('//format_number(h%px(k))//', '// &
                format_number(h%py(k))//')'
      end select
   end function history_label

   !> Check the request against the model's histories (nothing drawn).
   subroutine check_request(h, req, error)
      type(history_t), intent(in) :: h
      type(history_request_t), intent(in) :: req
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      character(len=16) :: a, b
      do k = 1, req%n
         if (req%ids(k) < 1 .or. req%ids(k) > h%n) then
            write (a, '(i0)') req%ids(k)
            write (b, '(i0)') h%n
            call set_error(error, 'PLOT HISTORY: history '//trim(a)// &
                           ' is not defined (histories defined: '//trim(b)//')')
            return
         end if
      end do
      if (req%abscissa /= 0 .and. (req%abscissa < 1 .or. req%abscissa > h%n)) then
         write (a, '(i0)') req%abscissa
         call set_error(error, 'PLOT AB: history '//trim(a)//' is not defined')
         return
      end if
      ! (xwin and ywin are fixed arrays: no guard needed for has_*)
      if (req%has_xwin .and. req%xwin(2) <= req%xwin(1)) then
         call set_error(error, 'PLOT XWINDOW: expected xl < xu')
      else if (req%has_ywin .and. req%ywin(2) <= req%ywin(1)) then
         call set_error(error, 'PLOT YWINDOW: expected yl < yu')
      end if
   end subroutine check_request

   !> Draw the curves of `req` on axes filling the scene's plotting square.
   subroutine plot_history_graph(scene, h, req, error)
      type(plot_scene_t), intent(inout) :: scene
      type(history_t), intent(in) :: h
      type(history_request_t), intent(in) :: req
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: xs(:), ys(:)
      real(wp) :: range(4), box(4), step, v, px, py, wtick
      integer :: k, ns, j, s_all
      character(len=:), allocatable :: xlabel
      call check_request(h, req, error)
      if (allocated(error)) return
      ns = h%nsample
      allocate (xs(ns), ys(ns))
      ! data ranges
      ! each curve from the first sample of its history (a HISTORY given
      ! after cycling starts later; with AB n, of history n too)
      range = [0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp]
      s_all = ns + 1
      do k = 1, req%n
         s_all = min(s_all, start(k))
      end do
      if (s_all <= ns) then
         call abscissa(xs)
         range(1:2) = [minval(xs(s_all:ns)), maxval(xs(s_all:ns))]
         range(3) = huge(1.0_wp)
         range(4) = -huge(1.0_wp)
         do k = 1, req%n
            if (start(k) > ns) cycle
            call ordinate(k, ys)
            range(3) = min(range(3), minval(ys(start(k):ns)))
            range(4) = max(range(4), maxval(ys(start(k):ns)))
         end do
      end if
      if (req%has_xwin) range(1:2) = req%xwin
      if (req%has_ywin) range(3:4) = req%ywin
      call widen_range(range(1:2))
      call widen_range(range(3:4))
      box = [scene%vx0 + 108.0_wp, scene%vx1 - 15.0_wp, scene%vy0 + 60.0_wp, scene%vy1 - 15.0_wp]
      call scene%set_view(range, box, .false.)
      ! grid, ticks and their labels
      step = tick_step(range(1:2), box(2) - box(1), 60.0_wp, .true.)
      if (max(abs(range(1)), abs(range(2))) > 1.0e6_wp*step) step = huge(1.0_wp)
      do j = ceiling(range(1)/step), floor(range(2)/step)
         v = real(j, wp)*step
         call scene%to_page(v, range(3), px, py)
         call scene%polyline(item_polyline, [px, px], [box(3), box(4)], light_grey, 0.8_wp)
         call scene%polyline(item_polyline, [px, px], [box(3), box(3) - 6.0_wp], black, 1.2_wp)
         call scene%text(format_tick(v), px, box(3) - 24.0_wp, 10.0_wp, black, &
                         align=align_centre)
      end do
      step = tick_step(range(3:4), box(4) - box(3), 45.0_wp, .false.)
      if (max(abs(range(3)), abs(range(4))) > 1.0e6_wp*step) step = huge(1.0_wp)
      wtick = 0.0_wp
      do j = ceiling(range(3)/step), floor(range(4)/step)
         v = real(j, wp)*step
         call scene%to_page(range(1), v, px, py)
         call scene%polyline(item_polyline, [box(1), box(2)], [py, py], light_grey, 0.8_wp)
         call scene%polyline(item_polyline, [box(1) - 6.0_wp, box(1)], [py, py], black, 1.2_wp)
         call scene%text(format_tick(v), box(1) - 10.0_wp, py - 5.0_wp, 10.0_wp, black, &
                         align=align_right)
         wtick = max(wtick, font_text_width(format_tick(v), 10.0_wp))
      end do
      if (range(3) < 0.0_wp .and. range(4) > 0.0_wp) then
         call scene%to_page(range(1), 0.0_wp, px, py)
         call scene%polyline(item_polyline, [box(1), box(2)], [py, py], grey, 1.0_wp)
      end if
      call scene%polyline(item_polygon, [box(1), box(2), box(2), box(1)], &
                          [box(3), box(3), box(4), box(4)], black, 1.5_wp)
      ! axis titles
      if (req%abscissa == 0) then
         xlabel = 'time (s)'
      else
         xlabel = 'history '//itoa(req%abscissa)//': '//history_label(h, req%abscissa)// &
                  unit_suffix(h%kind(req%abscissa))
      end if
      if (req%xrev) xlabel = '-('//xlabel//')'
      call scene%text(xlabel, 0.5_wp*(box(1) + box(2)), box(3) - 48.0_wp, 13.0_wp, black, &
                      align=align_centre)
      ! the y title left of the widest tick label (10 points from the
      ! axis), its 13-point glyphs centred 8 points further out
      if (req%n == 1) then
         call scene%text(trim(merge('-', ' ', req%yrev)//trim(hist_keyword(h%kind(req%ids(1))))// &
                         unit_suffix(h%kind(req%ids(1)))), &
                         box(1) - 10.0_wp - wtick - 12.0_wp, 0.5_wp*(box(3) + box(4)), 13.0_wp, &
                         black, align=align_centre, angle=90.0_wp)
      else if (req%n > 1) then
         ! several curves share the axis: the unit when they have one
         if (all([(hist_unit(h%kind(req%ids(j))) == hist_unit(h%kind(req%ids(1))), &
                   j = 1, req%n)]) .and. len_trim(hist_unit(h%kind(req%ids(1)))) > 0) &
            call scene%text(trim(hist_unit(h%kind(req%ids(1)))), &
                            box(1) - 10.0_wp - wtick - 12.0_wp, 0.5_wp*(box(3) + box(4)), &
                            13.0_wp, black, align=align_centre, angle=90.0_wp)
      end if
      ! curves
      call scene%add_legend(legend_title, 'history plot')
      if (req%n == 0) then
         call scene%add_legend(legend_text, '(no histories defined)')
      else if (ns == 0) then
         call scene%add_legend(legend_text, '(no samples recorded yet)')
      end if
      do k = 1, req%n
         if (ns - start(k) >= 1) then
            call abscissa(xs)
            call ordinate(k, ys)
            call scene%world_polyline(item_polyline, xs(start(k):ns), ys(start(k):ns), &
                                      series_colour(k), 1.8_wp)
         else if (ns == start(k)) then
            ! one sample (a history defined just before the last sample):
            ! a cross marks it, a one-point line would not show
            call abscissa(xs)
            call ordinate(k, ys)
            if (xs(ns) >= range(1) .and. xs(ns) <= range(2) .and. &
                ys(ns) >= range(3) .and. ys(ns) <= range(4)) then
               call scene%to_page(xs(ns), ys(ns), px, py)
               call scene%polyline(item_polyline, [px - 5.0_wp, px + 5.0_wp], &
                                   [py - 5.0_wp, py + 5.0_wp], series_colour(k), 1.8_wp)
               call scene%polyline(item_polyline, [px - 5.0_wp, px + 5.0_wp], &
                                   [py + 5.0_wp, py - 5.0_wp], series_colour(k), 1.8_wp)
            end if
         end if
         call scene%add_legend(legend_line, merge('-', ' ', req%yrev)//itoa(req%ids(k))//' '// &
                               history_label(h, req%ids(k))//unit_suffix(h%kind(req%ids(k))), &
                               colour=series_colour(k), &
                               width=2.0_wp)
      end do
      if (ns > 0) call scene%add_legend(legend_text, itoa(ns)//' samples, cycles '// &
                                        itoa(int(h%step(1)))//' to '//itoa(int(h%step(ns))))
      if (req%abscissa == 0) then
         call scene%add_legend(legend_text, 'vs. time')
      else
         call scene%add_legend(legend_text, 'vs. history '//itoa(req%abscissa))
      end if
   contains
      !> ' (unit)' of a history kind, empty when it has none.
      function unit_suffix(kind) result(text)
         integer, intent(in) :: kind
         character(len=:), allocatable :: text
         text = ''
         if (len_trim(hist_unit(kind)) > 0) text = ' ('//trim(hist_unit(kind))//')'
      end function unit_suffix
      integer function start(k) result(s0)
         integer, intent(in) :: k
         s0 = int(history_first(h, req%ids(k)))
         if (req%abscissa /= 0) s0 = max(s0, int(history_first(h, req%abscissa)))
      end function start
      subroutine abscissa(a)
         real(wp), intent(out) :: a(:)
         if (req%abscissa == 0) then
            a = h%time(1:ns)
         else
            a = h%values(req%abscissa, 1:ns)
         end if
         if (req%xrev) a = -a
      end subroutine abscissa
      subroutine ordinate(k, a)
         integer, intent(in) :: k
         real(wp), intent(out) :: a(:)
         a = h%values(req%ids(k), 1:ns)
         if (req%yrev) a = -a
      end subroutine ordinate
   end subroutine plot_history_graph

   !> Axis step: a 1-2-5 value giving at most 8 ticks, each at least
   !> `room` page units (plus the widest label) apart along `length`.
   function tick_step(r, length, room, horizontal) result(step)
      real(wp), intent(in) :: r(2), length, room
      logical, intent(in) :: horizontal
      real(wp) :: step, wlabel
      integer :: guard
      step = nice_number((r(2) - r(1))/8.0_wp)
      do guard = 1, 20
         wlabel = max(font_text_width(format_tick(r(1)), 10.0_wp), &
                      font_text_width(format_tick(r(2)), 10.0_wp), &
                      font_text_width(format_tick(r(1) + step), 10.0_wp))
         if (.not. horizontal) wlabel = 0.0_wp     ! vertical axis: labels stack
         if (step/(r(2) - r(1))*length >= room + wlabel) exit
         step = next_step(step)
      end do
   end function tick_step

   !> The 1-2-5 value after `step`.
   pure real(wp) function next_step(step) result(n)
      real(wp), intent(in) :: step
      real(wp) :: p, f
      p = 10.0_wp**floor(log10(step) + 1.0e-9_wp)
      f = step/p
      if (f < 1.5_wp) then
         n = 2.0_wp*p
      else if (f < 3.5_wp) then
         n = 5.0_wp*p
      else
         n = 10.0_wp*p
      end if
   end function next_step

   !> A range of zero width gets a width, and a little room either side (the
   !> axes of PLOT HISTORY and PLOT THIST).
   pure subroutine widen_range(r)
      real(wp), intent(inout) :: r(2)
      real(wp) :: d
      d = r(2) - r(1)
      if (d <= 0.0_wp) then
         d = max(abs(r(1)), 1.0e-30_wp)*0.1_wp
         if (r(1) == 0.0_wp) d = 1.0_wp
         r = [r(1) - d, r(2) + d]
      end if
   end subroutine widen_range


end module plot_history
