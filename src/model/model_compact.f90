!> Dense corner ids (issue 23). Cutting (JSET, CRACK, SPLIT, TUNNEL, ARC)
!> replaces a block's ring of corners and DELETE drops one; the old ids go
!> dead. Left in the list they were half the corner list at 100k blocks
!> (321 bytes a block) and every per-corner pass of the cycle (the edge
!> frames) walked them. `model_compact_corners` renumbers the live corners
!> 1..n in their old order (so every loop over corners meets them in the
!> same order: the same sums, the same nearest-corner ties, the same bits)
!> and rewrites every holder of a corner id. It runs after each command,
!> right after the 1989 addresses are synchronised (model_address): the
!> corners gone since the last synchronisation have then given their
!> records back, so no dead slot is needed for address matching any more.
!>
!> Corner ids are labels (PRINT CORNERS, EXPORT .vtu, HISTORY at a corner);
!> the 1989 address of a corner (BOUNDARY CORNER by address, PRINT ADDRESS)
!> does not change. A model whose lists still point at a dead corner (a
!> boundary point, BE node, liner interface or heat record on a deleted
!> block, a contact carrying forces that the next scan will break, a corner
!> whose record is not yet given back) keeps its holes until they go: the
!> model then works as before, only larger.
module model_compact
   use core_kinds, only: ip, i1
   use model_state, only: model_t
   use model_geometry, only: geometry_release_slack
   use model_history, only: hist_xvel, hist_ydis, hist_address
   use model_address, only: ak_corner
   use model_thermal, only: bc_source
   implicit none
   private
   public :: model_compact_corners

contains

   !> Renumber the live corners 1..n (old order) when some are dead and no
   !> holder still needs a dead one (module header); `done`: renumbered.
   subroutine model_compact_corners(model, done)
      type(model_t), intent(inout) :: model
      logical, intent(out), optional :: done
      integer(ip), allocatable :: rank(:)
      integer(ip) :: n, nlive, i
      if (present(done)) done = .false.
      n = model%geometry%corners%n
      if (n <= 0) return
      allocate (rank(0:n))
      rank(0) = 0
      do i = 1, n
         rank(i) = rank(i - 1)
         if (model%geometry%corners%live(i)) rank(i) = rank(i) + 1
      end do
      nlive = rank(n)
      if (nlive == n) return
      if (dead_needed(model, rank)) return
      call move_corners(model, rank)
      call remap_holders(model, rank)
      model%geometry%corners%n = nlive
      ! the corners there at the last search keep the ids below the new
      ! ones' (the order is kept): engine_cycle search_base
      if (model%mech%search_sizes(2) > 0) &
         model%mech%search_sizes(2) = rank(min(model%mech%search_sizes(2), n))
      ! the list's slots beyond the live count go back (geometry_release_slack)
      call geometry_release_slack(model%geometry, 1)
      if (present(done)) done = .true.
   end subroutine model_compact_corners

   !> New id of old corner k: rank(k) when k is live, 0 when dead or 0.
   pure integer(ip) function new_id(rank, k)
      integer(ip), intent(in) :: rank(0:), k
      new_id = 0
      if (k < 1 .or. k > ubound(rank, 1)) return
      if (rank(k) > rank(k - 1)) new_id = rank(k)
   end function new_id

   !> Does any list still point at a dead corner whose reader would need it?
   logical function dead_needed(model, rank) result(needed)
      type(model_t), intent(in) :: model
      integer(ip), intent(in) :: rank(0:)
      integer(ip) :: i
      needed = .true.
      associate (geo => model%geometry, bnd => model%bound)
         ! a dead corner not yet given back to the junk list (model_address)
         associate (t => geo%ia%tab(ak_corner))
            if (allocated(t%synced)) then
               do i = 1, min(t%nsynced, size(rank, kind=ip) - 1_ip)
                  if (t%synced(i) /= 0_i1 .and. is_dead(i)) return
               end do
            end if
         end associate
         do i = 1, bnd%n
            if (is_dead(bnd%corner(i))) return
            if (allocated(bnd%end_prev)) then
               if (is_dead(bnd%end_prev(i)) .or. is_dead(bnd%end_next(i))) return
            end if
         end do
         if (allocated(model%be%corner)) then
            do i = 1, model%be%nc
               if (is_dead(model%be%corner(i))) return
            end do
         end if
         if (allocated(model%structures)) then
            associate (it => model%structures%interfaces)
               do i = 1, it%n
                  if (is_dead(it%edge(i))) return
               end do
            end associate
         end if
         if (allocated(model%thermal)) then
            associate (th => model%thermal)
               do i = 1, th%nrec
                  if (th%rec_kind(i) /= bc_source .and. is_dead(th%rec_id(i))) return
               end do
               do i = 1, th%nthis
                  if (th%this_kind(i) == 1 .and. is_dead(th%this_gp(i))) return
               end do
            end associate
         end if
         ! contacts carrying forces are updated in place (contact_update
         ! kills those whose corners are gone); set-up contacts out of date
         ! are rebuilt from scratch and read no corner id before
         if (geo%mechanical .or. geo%contacts_valid) then
            do i = 1, geo%contacts%n
               if (.not. geo%contacts%live(i)) cycle
               if (is_dead(geo%contacts%end1(i)) .or. is_dead(geo%contacts%end2(i))) return
            end do
         end if
      end associate
      needed = .false.
   contains
      pure logical function is_dead(k)
         integer(ip), intent(in) :: k
         is_dead = .false.
         if (k < 1 .or. k > ubound(rank, 1)) return
         is_dead = rank(k) == rank(k - 1)
      end function is_dead
   end function dead_needed

   !> Live corner k moves to slot rank(k) (never up: in place, in order);
   !> its ring links follow.
   subroutine move_corners(model, rank)
      type(model_t), intent(inout) :: model
      integer(ip), intent(in) :: rank(0:)
      integer(ip) :: i, j, n
      associate (co => model%geometry%corners)
         n = co%n
         do i = 1, n
            if (.not. co%live(i)) cycle
            j = rank(i)
            if (j == i) cycle
            co%x(j) = co%x(i); co%y(j) = co%y(i)
            co%rx(j) = co%rx(i); co%ry(j) = co%ry(i); co%radius(j) = co%radius(i)
            co%ux(j) = co%ux(i); co%uy(j) = co%uy(i)
            co%block(j) = co%block(i); co%next(j) = co%next(i); co%prev(j) = co%prev(i)
            co%gp(j) = co%gp(i); co%addr(j) = co%addr(i)
         end do
         j = rank(n)
         do i = 1, j
            co%next(i) = new_id(rank, co%next(i))
            co%prev(i) = new_id(rank, co%prev(i))
         end do
         co%live(1:j) = .true.
         co%live(j + 1:n) = .false.
      end associate
   end subroutine move_corners

   !> Every list that names a corner names it by its new id (a dead one: 0).
   subroutine remap_holders(model, rank)
      type(model_t), intent(inout) :: model
      integer(ip), intent(in) :: rank(0:)
      integer(ip) :: i, k, n
      n = ubound(rank, 1)
      associate (geo => model%geometry)
         do i = 1, geo%blocks%n
            geo%blocks%first_corner(i) = new_id(rank, geo%blocks%first_corner(i))
         end do
         associate (ct => geo%contacts)
            do i = 1, ct%n
               ct%end1(i) = new_id(rank, ct%end1(i))
               ct%end2(i) = new_id(rank, ct%end2(i))
            end do
         end associate
         do i = 1, geo%gridpoints%n
            geo%gridpoints%corner(i) = new_id(rank, geo%gridpoints%corner(i))
         end do
         ! 1989 address marks: one byte a corner id (model_address)
         associate (t => geo%ia%tab(ak_corner))
            if (allocated(t%synced)) then
               k = min(t%nsynced, n)
               do i = 1, k
                  if (new_id(rank, i) > 0) t%synced(rank(i)) = t%synced(i)
               end do
               t%nsynced = rank(k)
            end if
         end associate
      end associate
      associate (bnd => model%bound)
         do i = 1, bnd%n
            bnd%corner(i) = new_id(rank, bnd%corner(i))
            if (allocated(bnd%end_prev)) then
               bnd%end_prev(i) = new_id(rank, bnd%end_prev(i))
               bnd%end_next(i) = new_id(rank, bnd%end_next(i))
            end if
         end do
         ! corners above the mark are new since the last BOUNDARY: the same ones
         bnd%corners_seen = rank(min(max(bnd%corners_seen, 0_ip), n))
      end associate
      if (allocated(model%be%corner)) then
         do i = 1, model%be%nc
            model%be%corner(i) = new_id(rank, model%be%corner(i))
         end do
      end if
      if (allocated(model%structures)) then
         associate (it => model%structures%interfaces)
            do i = 1, it%n
               it%edge(i) = new_id(rank, it%edge(i))
            end do
         end associate
      end if
      associate (h => model%hist)
         do i = 1, h%n
            if (h%kind(i) >= hist_xvel .and. h%kind(i) <= hist_ydis) then
               ! a dead corner: sampling looks for the nearest one again (engine_history)
               h%entity(i) = new_id(rank, h%entity(i))
            else if (h%kind(i) == hist_address) then
               if (nint(h%x(i)) == ak_corner) h%entity(i) = new_id(rank, h%entity(i))
            end if
         end do
      end associate
      if (allocated(model%thermal)) call remap_thermal(model, rank)
   end subroutine remap_holders

   !> Temperatures of rigid-block corners (indexed by corner id), the heat
   !> records and temperature histories at corners.
   subroutine remap_thermal(model, rank)
      type(model_t), intent(inout) :: model
      integer(ip), intent(in) :: rank(0:)
      integer(ip) :: i, j, m
      associate (th => model%thermal)
         m = min(th%nc, ubound(rank, 1))
         do i = 1, m
            j = new_id(rank, i)
            if (j == 0 .or. j == i) cycle
            th%ctemp(j) = th%ctemp(i)
            th%cdtacc(j) = th%cdtacc(i)
            th%cfixed(j) = th%cfixed(i)
         end do
         ! entries beyond the last corner stand for none
         if (th%nc > 0) th%nc = rank(m)
         do i = 1, th%nrec
            if (th%rec_kind(i) /= bc_source) th%rec_id(i) = new_id(rank, th%rec_id(i))
         end do
         do i = 1, th%nthis
            if (th%this_kind(i) == 1) th%this_gp(i) = new_id(rank, th%this_gp(i))
         end do
      end associate
   end subroutine remap_thermal

end module model_compact
