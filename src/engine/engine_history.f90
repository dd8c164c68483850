!> HISTORY variables: where they are measured and their current values
!> (manual Section 4.5 HISTORY). Point variables (XVEL YVEL XDIS YDIS) are
!> taken at the block corner nearest the point asked for; among corners at
!> the same place (within 1 % of the rounding length) the one of the block
!> whose centroid is nearest wins (so
!> that (10,20) in the tutorial picks the corner (5,20) of the sliding top
!> block, not of the buttress block that is later deleted). If that corner
!> is deleted, the nearest live corner is taken again.
module engine_history
   use core_kinds, only: wp, ip
   use model_geometry, only: geometry_t
   use model_mechanics, only: mechanics_t
   use model_history, only: history_t, hist_xvel, hist_yvel, hist_xdis, hist_ydis, hist_bfx, &
                            hist_bfy, hist_bfm, hist_ndis, hist_sdis, hist_nstr, hist_sstr, &
                            hist_unbal, hist_damp, history_record
   implicit none
   private
   public :: nearest_corner, history_values, history_sample

contains

   !> Live corner nearest (x, y); 0 if there is none.
   pure function nearest_corner(geo, x, y) result(best)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x, y
      integer(ip) :: best
      integer(ip) :: c, b
      real(wp) :: d, dbest, cb, cbest, tie
      best = 0
      dbest = huge(1.0_wp)
      cbest = huge(1.0_wp)
      tie = max(100.0_wp*geo%tol, 0.01_wp*geo%round)
      do c = 1, geo%corners%n
         if (.not. geo%corners%live(c)) cycle
         d = hypot(geo%corners%x(c) - x, geo%corners%y(c) - y)
         b = geo%corners%block(c)
         cb = hypot(geo%blocks%xc(b) - x, geo%blocks%yc(b) - y)
         if (d < dbest - tie .or. (d <= dbest + tie .and. cb < cbest)) then
            best = c
            dbest = min(d, dbest)
            cbest = cb
         end if
      end do
   end function nearest_corner

   !> Current value of every history variable.
   subroutine history_values(h, geo, mech, vals)
      type(history_t), intent(inout) :: h
      type(geometry_t), intent(in) :: geo
      type(mechanics_t), intent(in) :: mech
      real(wp), intent(out) :: vals(:)
      integer :: i
      integer(ip) :: c, b, k
      real(wp) :: l
      do i = 1, h%n
         vals(i) = 0.0_wp
         k = h%entity(i)
         select case (h%kind(i))
         case (hist_xvel, hist_yvel, hist_xdis, hist_ydis)
            c = k
            if (c > 0) then
               if (.not. geo%corners%live(c)) c = 0
            end if
            if (c == 0) then
               c = nearest_corner(geo, h%x(i), h%y(i))
               h%entity(i) = c
               if (c > 0) then
                  h%px(i) = geo%corners%x(c)
                  h%py(i) = geo%corners%y(c)
               end if
            end if
            if (c == 0) cycle
            b = geo%corners%block(c)
            select case (h%kind(i))
            case (hist_xvel)
               vals(i) = geo%blocks%vx(b) - geo%blocks%vr(b)*(geo%corners%y(c) - geo%blocks%yc(b))
            case (hist_yvel)
               vals(i) = geo%blocks%vy(b) + geo%blocks%vr(b)*(geo%corners%x(c) - geo%blocks%xc(b))
            case (hist_xdis)
               vals(i) = geo%corners%ux(c)
            case default
               vals(i) = geo%corners%uy(c)
            end select
         case (hist_bfx, hist_bfy, hist_bfm)
            if (k < 1 .or. k > geo%blocks%n) cycle
            if (.not. geo%blocks%live(k)) cycle
            select case (h%kind(i))
            case (hist_bfx)
               vals(i) = geo%blocks%fx(k)
            case (hist_bfy)
               vals(i) = geo%blocks%fy(k)
            case default
               vals(i) = geo%blocks%fm(k)
            end select
         case (hist_ndis, hist_sdis, hist_nstr, hist_sstr)
            if (k < 1 .or. k > geo%contacts%n) cycle
            if (.not. geo%contacts%live(k)) cycle
            l = geo%contacts%length(k)
            select case (h%kind(i))
            case (hist_ndis)
               vals(i) = geo%contacts%state%un(k)
            case (hist_sdis)
               vals(i) = geo%contacts%state%us(k)
            case (hist_nstr)
               ! stresses: tension positive (Section 4.1), force / length
               if (l > 0.0_wp) vals(i) = -geo%contacts%state%fn(k)/l
            case default
               if (l > 0.0_wp) vals(i) = geo%contacts%state%fs(k)/l
            end select
         case (hist_unbal)
            vals(i) = mech%unbalanced
         case (hist_damp)
            vals(i) = mech%auto_alpha
         end select
      end do
   end subroutine history_values

   !> Record one sample of all variables at the current time.
   subroutine history_sample(h, geo, mech, vals)
      type(history_t), intent(inout) :: h
      type(geometry_t), intent(in) :: geo
      type(mechanics_t), intent(in) :: mech
      real(wp), intent(inout) :: vals(:)
      if (h%n == 0) return
      call history_values(h, geo, mech, vals)
      call history_record(h, mech%time, int(mech%step, ip), vals)
   end subroutine history_sample

end module engine_history
