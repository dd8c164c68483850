!> PLOT THIST n1 <n2 ..> (UDEC manual (ICG1.5, 1989), Section 7.4.2, PLOT:
!> "temperature histories n1, n2 ... assigned by THIST command"): the
!> temperature samples of the chosen thermal histories against thermal time,
!> as curves on axes with a legend (the layout of PLOT HISTORY, drawn here
!> from the thermal part of the model).
module plot_thist
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: itoa
   use model_state, only: model_t
   use model_thermal, only: max_thist
   use plot_legend, only: plot_compose_legend
   use plot_history, only: widen_range
   use plot_scene, only: plot_scene_t, item_polyline, item_polygon, legend_text, legend_line, &
                         legend_title, black, light_grey, series_colour, format_number, &
                         format_tick, nice_number, align_centre, align_right
   implicit none
   private
   public :: plot_thist_scene

contains

   !> The scene of PLOT THIST ids (nothing drawn on error).
   subroutine plot_thist_scene(model, ids, heading, scene, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: ids(:)
      logical, intent(in) :: heading
      type(plot_scene_t), intent(out) :: scene
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: xs(:), ys(:)
      real(wp) :: range(4), box(4), step, v, px, py
      integer :: k, j
      integer(ip) :: ns, s
      if (.not. allocated(model%thermal)) then
         call set_error(error, 'PLOT THIST: the model has no thermal part (give THERMAL)')
         return
      end if
      if (size(ids) == 0) then
         call set_error(error, 'PLOT THIST: expected history numbers n1 <n2 ..> (THIST LIST ' &
                        //'lists them)')
         return
      end if
      associate (th => model%thermal)
         do k = 1, size(ids)
            if (ids(k) < 1 .or. ids(k) > th%nthis) then
               call set_error(error, 'PLOT THIST: thermal history '//itoa(ids(k))// &
                              ' is not defined (thermal histories defined: '//itoa(th%nthis)//')')
               return
            end if
         end do
         call scene%init(heading)
         scene%heading = model%heading
         scene%time = th%time
         scene%cycle = th%nsteps
         scene%what = 'THIST'
         ns = th%nsamp
         allocate (xs(ns), ys(ns))
         range = [0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp]
         if (ns > 0) then
            xs = th%samp_time(1:ns)
            range(1:2) = [minval(xs), maxval(xs)]
            range(3) = huge(1.0_wp)
            range(4) = -huge(1.0_wp)
            do k = 1, size(ids)
               call values(ids(k))
               range(3) = min(range(3), minval(ys))
               range(4) = max(range(4), maxval(ys))
            end do
         end if
         call widen_range(range(1:2))
         call widen_range(range(3:4))
         box = [scene%vx0 + 108.0_wp, scene%vx1 - 15.0_wp, scene%vy0 + 60.0_wp, &
                scene%vy1 - 15.0_wp]
         call scene%set_view(range, box, .false.)
         ! ticks: 1-2-5 steps, about six per axis
         step = nice_number((range(2) - range(1))/6.0_wp)
         do j = ceiling(range(1)/step), floor(range(2)/step)
            v = real(j, wp)*step
            call scene%to_page(v, range(3), px, py)
            call scene%polyline(item_polyline, [px, px], [box(3), box(4)], light_grey, 0.8_wp)
            call scene%text(format_tick(v), px, box(3) - 24.0_wp, 10.0_wp, black, &
                            align=align_centre)
         end do
         step = nice_number((range(4) - range(3))/6.0_wp)
         do j = ceiling(range(3)/step), floor(range(4)/step)
            v = real(j, wp)*step
            call scene%to_page(range(1), v, px, py)
            call scene%polyline(item_polyline, [box(1), box(2)], [py, py], light_grey, 0.8_wp)
            call scene%text(format_tick(v), box(1) - 10.0_wp, py - 5.0_wp, 10.0_wp, black, &
                            align=align_right)
         end do
         call scene%polyline(item_polygon, [box(1), box(2), box(2), box(1)], &
                             [box(3), box(3), box(4), box(4)], black, 1.5_wp)
         call scene%text('thermal time (s)', 0.5_wp*(box(1) + box(2)), box(3) - 48.0_wp, &
                         13.0_wp, black, align=align_centre)
         call scene%text('temperature', box(1) - 80.0_wp, 0.5_wp*(box(3) + box(4)), 13.0_wp, &
                         black, align=align_centre, angle=90.0_wp)
         call scene%add_legend(legend_title, 'thermal history plot')
         if (ns == 0) call scene%add_legend(legend_text, '(no samples recorded yet: RUN)')
         do k = 1, size(ids)
            if (ns >= 2) then
               call values(ids(k))
               call scene%world_polyline(item_polyline, xs, ys, series_colour(k), 1.8_wp)
            end if
            call scene%add_legend(legend_line, itoa(ids(k))//' T at ('// &
                                  format_number(th%this_x(ids(k)))//', '// &
                                  format_number(th%this_y(ids(k)))//')', &
                                  colour=series_colour(k), width=2.0_wp)
         end do
         if (ns > 0) call scene%add_legend(legend_text, itoa(ns)//' samples, every '// &
                                           itoa(th%ntcyc)//' thermal steps')
      end associate
      call plot_compose_legend(scene)
   contains
      subroutine values(h)
         integer, intent(in) :: h
         do s = 1, ns
            ys(s) = model%thermal%samp_val((s - 1)*max_thist + h)
         end do
      end subroutine values
   end subroutine plot_thist_scene

end module plot_thist
