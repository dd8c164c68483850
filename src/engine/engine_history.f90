!> HISTORY variables: where they are measured and their current values
!> (manual Section 4.5 HISTORY). Point variables (XVEL YVEL XDIS YDIS) are
!> taken at the gridpoint of a deformable block nearest the point asked for
!> when it is nearer than every rigid-block corner (kinds hist_gxvel ..),
!> else at the nearest rigid-block corner; among corners at
!> the same place (within 1 % of the rounding length) the one of the block
!> whose centroid is nearest wins (so
!> that (10,20) in the tutorial picks the corner (5,20) of the sliding top
!> block, not of the buttress block that is later deleted). Stress
!> variables (SXX SXY SYY) are taken in the zone whose centroid is nearest
!> (ties to the lower id). If the corner, gridpoint or zone is deleted (or
!> the corner's block is zoned), the point is located again. Gridpoints of
!> excavated (CONS 0) blocks, and their zones, count as deleted (CHANGE
!> CONS 0 opens the same hole as DELETE): a point on the wall of an
!> excavation is taken in the rock, not at the coincident gridpoint of the
!> null block, whose displacement stays zero; only when every gridpoint
!> (zone) is in a null block is one of those used.
module engine_history
   use model_address, only: address_field
   use model_fluid, only: fluid_t
   use model_reinforcement, only: reinforcement_t
   use core_kinds, only: wp, ip
   use model_geometry, only: geometry_t, joint_state_value
   use model_mechanics, only: mechanics_t, damping_local
   use model_history, only: history_t, hist_xvel, hist_yvel, hist_xdis, hist_ydis, hist_bfx, &
                            hist_bfy, hist_bfm, hist_ndis, hist_sdis, hist_nstr, hist_sstr, hist_address, &
                           hist_caxial, hist_raxial, hist_rshear, hist_srat, &
                            hist_unbal, hist_damp, hist_xhis, hist_yhis, &
                            hist_gxvel, hist_gyvel, &
                            hist_gxdis, hist_gydis, hist_sxx, hist_sxy, hist_syy, &
                            hist_gridpoint_kind
   use model_zone_fields, only: nearest_zone, nearest_gridpoint, zone_centroid
   use model_materials, only: material_table_t
   use contact_mechanics, only: joint_props_of
   use contact_joint_law, only: joint_shear_ratio
   implicit none
   private
   public :: nearest_corner, history_values, history_locate, history_reattach

contains

   !> Live rigid-block corner nearest (x, y); 0 if there is none. Corners
   !> of zoned blocks (with a gridpoint) are left to the gridpoints.
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
         if (geo%corners%gp(c) > 0) cycle
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

   !> Where a point or stress variable of `kind` asked at (x, y) is taken:
   !> `kind_out` (a point kind becomes its gridpoint kind when a gridpoint is
   !> strictly nearer than every rigid-block corner), the corner, gridpoint
   !> or zone id `entity` (0: nothing to measure yet) and the point used.
   !> Other kinds come back unchanged with entity 0.
   pure subroutine history_locate(geo, kind, x, y, kind_out, entity, px, py)
      type(geometry_t), intent(in) :: geo
      integer, intent(in) :: kind
      real(wp), intent(in) :: x, y
      integer, intent(out) :: kind_out
      integer(ip), intent(out) :: entity
      real(wp), intent(out) :: px, py
      integer(ip) :: c, g
      real(wp) :: dg, dc
      kind_out = kind
      entity = 0
      px = x
      py = y
      select case (kind)
      case (hist_xvel, hist_yvel, hist_xdis, hist_ydis, hist_gxvel, hist_gyvel, hist_gxdis, &
            hist_gydis)
         c = nearest_corner(geo, x, y)
         call nearest_gridpoint(geo, x, y, g, dg, solid=.true.)
         if (g == 0) call nearest_gridpoint(geo, x, y, g, dg)
         dc = huge(1.0_wp)
         if (c > 0) dc = hypot(geo%corners%x(c) - x, geo%corners%y(c) - y)
         if (g > 0 .and. dg < dc) then
            kind_out = hist_gridpoint_kind(kind, .true.)
            entity = g
            px = geo%gridpoints%x(g)
            py = geo%gridpoints%y(g)
         else
            kind_out = hist_gridpoint_kind(kind, .false.)
            if (c > 0) then
               entity = c
               px = geo%corners%x(c)
               py = geo%corners%y(c)
            end if
         end if
      case (hist_sxx, hist_sxy, hist_syy)
         entity = nearest_zone(geo, x, y, solid=.true.)
         if (entity == 0) entity = nearest_zone(geo, x, y)
         if (entity > 0) call zone_centroid(geo, entity, px, py)
      end select
   end subroutine history_locate

   !> Point histories (XVEL .. YDIS, SXX .. SYY) whose corner, gridpoint or
   !> zone is gone (DELETE) or excavated move now to the nearest one left, as
   !> sampling would do silently; `moved(i)` says which moved, so that DELETE
   !> can say so (a new user's wall history sat on the plug's gridpoint at the
   !> same place and moved to the wall's without a word).
   subroutine history_reattach(h, geo, moved)
      type(history_t), intent(inout) :: h
      type(geometry_t), intent(in) :: geo
      logical, intent(out) :: moved(:)
      integer :: i, kind_new
      integer(ip) :: c
      real(wp) :: px, py
      moved = .false.
      do i = 1, h%n
         select case (h%kind(i))
         case (hist_xvel, hist_yvel, hist_xdis, hist_ydis, hist_gxvel, hist_gyvel, hist_gxdis, &
               hist_gydis, hist_sxx, hist_sxy, hist_syy)
            if (h%entity(i) < 1) cycle
            if (entity_valid(h, i, geo)) cycle
            call history_locate(geo, h%kind(i), h%x(i), h%y(i), kind_new, c, px, py)
            h%kind(i) = kind_new
            h%entity(i) = c
            h%px(i) = px
            h%py(i) = py
            moved(i) = .true.
         end select
      end do
   end subroutine history_reattach

   !> Is the entity of variable i still there to be measured?
   pure logical function entity_valid(h, i, geo) result(ok)
      type(history_t), intent(in) :: h
      integer, intent(in) :: i
      type(geometry_t), intent(in) :: geo
      integer(ip) :: k
      k = h%entity(i)
      ok = .false.
      if (k < 1) return
      select case (h%kind(i))
      case (hist_xvel, hist_yvel, hist_xdis, hist_ydis)
         if (k > geo%corners%n) return
         ok = geo%corners%live(k)
         if (ok) ok = geo%corners%gp(k) == 0
      case (hist_gxvel, hist_gyvel, hist_gxdis, hist_gydis)
         if (k > geo%gridpoints%n) return
         ok = geo%gridpoints%live(k)
         ! an excavated block's gridpoint: look again for one in the rock
         if (ok) ok = geo%blocks%cons(geo%gridpoints%block(k)) /= 0
      case (hist_sxx, hist_sxy, hist_syy)
         if (k > geo%zones%n) return
         ok = geo%zones%live(k)
         if (ok) ok = geo%blocks%cons(geo%zones%block(k)) /= 0
      end select
   end function entity_valid

   !> Current value of every history variable.
   !> `mats` (the joint properties) is needed by SRAT only; without it SRAT reads 0.
   subroutine history_values(h, geo, mech, vals, fluid, reinf, mats)
      type(history_t), intent(inout) :: h
      type(geometry_t), intent(in) :: geo
      type(mechanics_t), intent(in) :: mech
      real(wp), intent(out) :: vals(:)
      type(fluid_t), intent(in), optional :: fluid
      type(reinforcement_t), intent(in), optional :: reinf
      type(material_table_t), intent(in), optional :: mats
      integer :: i, kind_new
      integer(ip) :: c, b, k
      real(wp) :: l, px, py, clemin
      do i = 1, h%n
         vals(i) = 0.0_wp
         k = h%entity(i)
         select case (h%kind(i))
         case (hist_caxial, hist_raxial, hist_rshear)
            ! reinforcement forces (Section 3.10); 0 when the element is gone
            if (.not. present(reinf)) cycle
            if (h%kind(i) == hist_caxial) then
               if (k >= 1 .and. k <= reinf%elements%n) vals(i) = reinf%elements%axial(k)
            else if (k >= 1 .and. k <= reinf%reinf%n) then
               if (h%kind(i) == hist_raxial) vals(i) = reinf%reinf%fa(k)
               if (h%kind(i) == hist_rshear) vals(i) = reinf%reinf%fs(k)
            end if
         case (hist_xvel, hist_yvel, hist_xdis, hist_ydis, hist_gxvel, hist_gyvel, hist_gxdis, &
               hist_gydis, hist_sxx, hist_sxy, hist_syy)
            if (.not. entity_valid(h, i, geo)) then
               call history_locate(geo, h%kind(i), h%x(i), h%y(i), kind_new, c, px, py)
               h%kind(i) = kind_new
               h%entity(i) = c
               h%px(i) = px
               h%py(i) = py
            end if
            c = h%entity(i)
            if (c == 0) cycle
            select case (h%kind(i))
            case (hist_gxvel); vals(i) = geo%gridpoints%vx(c)
            case (hist_gyvel); vals(i) = geo%gridpoints%vy(c)
            case (hist_gxdis); vals(i) = geo%gridpoints%ux(c)
            case (hist_gydis); vals(i) = geo%gridpoints%uy(c)
            case (hist_sxx); vals(i) = geo%zones%sxx(c)
            case (hist_sxy); vals(i) = geo%zones%sxy(c)
            case (hist_syy); vals(i) = geo%zones%syy(c)
            end select
            if (h%kind(i) > hist_ydis) cycle
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
               ! joint normal stress, compression positive (manual Section 4.1
               ! sign conventions: "joint normal force (stress) in compression"),
               ! as PRINT CONTACT FORCE prints it; force / length
               if (l > 0.0_wp) vals(i) = geo%contacts%state%fn(k)/l
            case default
               if (l > 0.0_wp) vals(i) = geo%contacts%state%fs(k)/l
            end select
         case (hist_srat)
            ! |shear| / strength of the contact's law now (joint_shear_ratio);
            ! the length the law scales by is the contact's, at least CLEMIN
            if (.not. present(mats)) cycle
            if (k < 1 .or. k > geo%contacts%n) cycle
            if (.not. geo%contacts%live(k)) cycle
            clemin = mech%clemin
            if (clemin <= 0.0_wp) clemin = mech%clemin_auto
            vals(i) = joint_shear_ratio(joint_props_of(mats, int(geo%contacts%jmat(k)), &
                                                       int(geo%contacts%jcons(k))), &
                                        int(geo%contacts%jcons(k)), geo%contacts%state%fn(k), &
                                        geo%contacts%state%fs(k), &
                                        max(geo%contacts%length(k), clemin), &
                                        joint_state_value(geo%contacts%state%phi_eff, k), &
                                        geo%contacts%state%flags(k))
         case (hist_address)
            call history_address_value(i)
         case (hist_unbal)
            vals(i) = mech%unbalanced
         case (hist_damp)
            ! DAMP AUTO's constant [1/s]; under DAMP LOCAL its fraction alpha
            vals(i) = merge(mech%local_alpha, mech%auto_alpha, mech%damping == damping_local)
         case (hist_xhis)
            vals(i) = mech%fxhis
         case (hist_yhis)
            vals(i) = mech%fyhis
         end select
      end do
   contains
      !> HISTORY ADDRESS i j: the word at offset j of the entity's record.
      subroutine history_address_value(iv)
         integer, intent(in) :: iv
         integer :: kind
         integer(ip) :: id
         character(len=:), allocatable :: name
         logical :: found
         id = h%entity(iv)
         kind = nint(h%x(iv))
         if (id < 1) return
         call address_field(geo, kind, id, nint(h%y(iv), ip), name, vals(iv), found, fluid)
      end subroutine history_address_value
   end subroutine history_values

end module engine_history
