!> The caption of every picture (manual Fig. 2-4): the heading across the
!> top, and a legend panel left of the plot with the problem time, the
!> cycle, the window, what is plotted and the scales of vectors and line
!> thicknesses (the legend entries the layers added).
module plot_legend
   use core_kinds, only: wp, i8
   use core_version, only: udec_name, udec_version
   use plot_scene, only: plot_scene_t, item_polyline, item_polygon, item_fill, &
                         legend_text, legend_swatch, legend_line, legend_arrow, legend_title, &
                         legend_bar, black, grey, format_number, align_left, align_centre
   use plot_font, only: font_text_width
   use core_output, only: itoa
   implicit none
   private
   public :: plot_compose_legend

   real(wp), parameter :: panel_x0 = 20.0_wp, panel_x1 = 400.0_wp
   real(wp), parameter :: text_size = 13.0_wp, line_step = 23.0_wp
   !> lowest baseline of a legend entry, and the smallest scale of a long legend
   real(wp), parameter :: bottom = 50.0_wp, min_shrink = 0.4_wp

contains

   !> Lay out heading and legend as scene items (once, after all layers).
   subroutine plot_compose_legend(scene)
      type(plot_scene_t), intent(inout) :: scene
      real(wp) :: y, size, x, needed, f, step, tsize, top
      integer :: k
      character(len=:), allocatable :: title
      if (.not. scene%heading_on) return
      ! title line: the heading, the cycle and the time (issue 24), shrunk
      ! to fit the page width
      title = 'cycle '//itoa(scene%cycle)//'   time '//format_number(scene%time)//' s'
      ! a heat model's time is the thermal time of RUN (the mechanical time
      ! stays 0 when RUN takes no mechanical steps)
      if (scene%thermal_time > 0.0_wp) title = title//'   thermal time '// &
         format_number(scene%thermal_time)//' s'
      if (len_trim(scene%heading) > 0) title = trim(scene%heading)//'   '//title
      size = fitted(title, 17.0_wp, scene%page_w - 40.0_wp)
      call scene%text(title, 0.5_wp*scene%page_w, scene%page_h - 42.0_wp, size, &
                      black, align=align_centre)
      call scene%polyline(item_polygon, [panel_x0, panel_x1, panel_x1, panel_x0], &
                          [20.0_wp, 20.0_wp, 780.0_wp, 780.0_wp], &
                          grey, 1.0_wp)
      y = 780.0_wp - 30.0_wp
      x = panel_x0 + 14.0_wp
      call scene%text('LEGEND', x, y, 15.0_wp, black)
      y = y - 1.3_wp*line_step
      call line('cycle  '//itoa(scene%cycle))
      call line('time   '//format_number(scene%time))
      if (scene%thermal_time > 0.0_wp) call line('thermal time '//format_number(scene%thermal_time))
      call line('window')
      call line('  x: '//format_number(scene%window(1))//' to '// &
                format_number(scene%window(2)))
      call line('  y: '//format_number(scene%window(3))//' to '// &
                format_number(scene%window(4)))
      if (len_trim(scene%what) > 0) call wrapped('plot: '//scene%what)
      y = y - 0.5_wp*line_step
      ! entries that would run past the bottom of the panel are set smaller
      ! (down to min_shrink); only beyond that are the last ones left out,
      ! and a line says how many
      needed = 0.0_wp
      do k = 1, scene%nlegend
         needed = needed + line_step
         if (scene%legend(k)%kind == legend_title) needed = needed + 0.3_wp*line_step
         if (scene%legend(k)%kind == legend_bar) then
            if (k == 1) then
               needed = needed + 0.5_wp*line_step
            else if (scene%legend(k - 1)%kind /= legend_bar) then
               needed = needed + 0.5_wp*line_step
            end if
            if (k == scene%nlegend) then
               needed = needed + line_step
            else if (scene%legend(k + 1)%kind /= legend_bar) then
               needed = needed + line_step
            end if
         end if
      end do
      f = 1.0_wp
      if (needed > y - bottom) f = max(min_shrink, (y - bottom)/needed)
      step = f*line_step
      tsize = f*text_size
      do k = 1, scene%nlegend
         if (y < bottom .or. (y - step < bottom .and. k < scene%nlegend .and. f <= min_shrink)) then
            call scene%text('('//itoa(int(scene%nlegend - k + 1, i8))// &
                            ' more legend entries not shown)', x, y, tsize, grey)
            exit
         end if
         associate (e => scene%legend(k))
            select case (e%kind)
            case (legend_title)
               y = y - 0.3_wp*step
               call scene%text(e%text, x, y, fitted(e%text, f*14.0_wp, panel_x1 - x - 10.0_wp), &
                               e%colour)
            case (legend_text)
               call scene%text(e%text, x + 12.0_wp, y, &
                               fitted(e%text, tsize, panel_x1 - x - 22.0_wp), e%colour)
            case (legend_swatch)
               call scene%polyline(item_fill, [x + 12.0_wp, x + 40.0_wp, x + 40.0_wp, &
                                   x + 12.0_wp], [y - 3.0_wp*f, y - 3.0_wp*f, y + 14.0_wp*f, &
                                   y + 14.0_wp*f], e%colour)
               call scene%polyline(item_polygon, [x + 12.0_wp, x + 40.0_wp, x + 40.0_wp, &
                                   x + 12.0_wp], [y - 3.0_wp*f, y - 3.0_wp*f, y + 14.0_wp*f, &
                                   y + 14.0_wp*f], grey, 0.8_wp)
               call scene%text(e%text, x + 52.0_wp, y, &
                               fitted(e%text, tsize, panel_x1 - x - 62.0_wp), black)
            case (legend_line)
               call scene%polyline(item_polyline, [x + 12.0_wp, x + 52.0_wp], &
                                   [y + 5.0_wp*f, y + 5.0_wp*f], e%colour, e%width)
               call scene%text(e%text, x + 64.0_wp, y, &
                               fitted(e%text, tsize, panel_x1 - x - 74.0_wp), black)
            case (legend_bar)
               ! bands of a colour bar touch: band k spans [y - 0.35 step,
               ! y + 0.65 step]; its upper edge is labelled, the lowest band
               ! of a run also its lower edge
               ! the top label stands above the first band: half a line more
               if (k == 1) then
                  y = y - 0.5_wp*step
               else if (scene%legend(k - 1)%kind /= legend_bar) then
                  y = y - 0.5_wp*step
               end if
               top = y + 0.65_wp*step
               call scene%polyline(item_fill, [x + 12.0_wp, x + 40.0_wp, x + 40.0_wp, &
                                   x + 12.0_wp], [top - step, top - step, top, top], e%colour)
               call scene%polyline(item_polyline, [x + 40.0_wp, x + 46.0_wp], [top, top], &
                                   black, 0.8_wp)
               call scene%text(e%text, x + 52.0_wp, top - 0.4_wp*tsize, &
                               fitted(e%text, tsize, panel_x1 - x - 62.0_wp), black)
               if (k == scene%nlegend) then
                  call bar_bottom()
               else if (scene%legend(k + 1)%kind /= legend_bar) then
                  call bar_bottom()
               end if
            case (legend_arrow)
               call scene%arrow(x + 12.0_wp, y + 5.0_wp*f, x + 12.0_wp + e%length, y + 5.0_wp*f, &
                                e%colour, 1.6_wp, .false.)
               call scene%text(e%text, x + 24.0_wp + e%length, y, tsize, black)
            end select
            y = y - step
         end associate
      end do
      call scene%text(udec_name//' '//udec_version, x, 32.0_wp, 10.0_wp, grey, align=align_left)
   contains
      !> Lower edge of the band just drawn (the last of its colour bar), its
      !> label, and the bar's outline; the next entry moves down a line.
      subroutine bar_bottom()
         integer :: j, nb
         real(wp) :: bot
         bot = top - step
         call scene%polyline(item_polyline, [x + 40.0_wp, x + 46.0_wp], [bot, bot], black, 0.8_wp)
         call scene%text(scene%legend(k)%low, x + 52.0_wp, bot - 0.4_wp*tsize, &
                         fitted(scene%legend(k)%low, tsize, panel_x1 - x - 62.0_wp), black)
         nb = 1
         do j = k - 1, 1, -1
            if (scene%legend(j)%kind /= legend_bar) exit
            nb = nb + 1
         end do
         call scene%polyline(item_polygon, [x + 12.0_wp, x + 40.0_wp, x + 40.0_wp, x + 12.0_wp], &
                             [bot, bot, bot + nb*step, bot + nb*step], grey, 0.8_wp)
         y = y - step
      end subroutine bar_bottom
      !> One legend line per run of words that fits the panel.
      subroutine wrapped(text)
         character(len=*), intent(in) :: text
         integer :: start, last, next
         start = 1
         do while (start <= len(text))
            last = len(text)
            do while (font_text_width(text(start:last), text_size) > panel_x1 - x - 10.0_wp)
               next = index(text(start:last - 1), ' ', back=.true.)
               if (next <= 1) exit
               last = start + next - 2
            end do
            call line(text(start:last))
            start = last + 1
            do while (start <= len(text))
               if (text(start:start) /= ' ') exit
               start = start + 1
            end do
         end do
      end subroutine wrapped
      subroutine line(text)
         character(len=*), intent(in) :: text
         call scene%text(text, x, y, fitted(text, text_size, panel_x1 - x - 10.0_wp), black)
         y = y - line_step
      end subroutine line
   end subroutine plot_compose_legend

   !> `size`, reduced so that `text` is at most `width` wide.
   pure real(wp) function fitted(text, size, width) result(s)
      character(len=*), intent(in) :: text
      real(wp), intent(in) :: size, width
      real(wp) :: w
      s = size
      w = font_text_width(text, size)
      if (w > width) s = size*width/w
   end function fitted


end module plot_legend
