!> Partners for the mixed discretization of plastic triangles.
!>
!> Constant-strain triangles lock under isochoric plastic flow: every
!> triangle must keep its own area, which leaves too few free motions for a
!> collapse mechanism (the CONS 3 caution of the manual's CHANGE command).
!> The 1989 program paired each triangle with a neighbour for the volumetric
!> part of the strain: its zone record holds KZLL, "pointer to neighboring
!> zone for mixed-discretization calculation" (manual Section 6). A pair of
!> triangles sharing an edge forms a quadrilateral that keeps one area
!> constraint instead of two, as the quadrilateral elements of Marti and
!> Cundall's mixed discretization do.
!>
!> The pairing is a matching on the zone adjacency graph (zones sharing an
!> edge), built greedily in the Karp-Sipser order: a zone with a single
!> unmatched neighbour is matched first (it has no other choice), otherwise
!> the next zone in order takes the unmatched neighbour with the fewest
!> unmatched neighbours of its own. A zone left without a partner points at
!> a matched neighbour one way, or at nothing when it has no eligible
!> neighbour; zones_mechanics (mixed_groups) then averages the leftover,
!> the neighbour and its partner as one group, so that the stiffness stays
!> symmetric. Cost O(zones).
module zones_mixed
   use core_kinds, only: ip
   use core_sort, only: counts_to_starts
   implicit none
   private
   public :: zone_partners

contains

   !> Partner of each of the n zones with vertices v(:, i) (gridpoint numbers
   !> 1..ngp): mate(i) = the zone i is averaged with, 0 for none; zones with
   !> eligible(i) false are neither paired nor partners. A pair is mutual
   !> (mate(mate(i)) == i) except for the one-way leftovers described above.
   subroutine zone_partners(v, eligible, ngp, mate)
      integer(ip), intent(in) :: v(:, :)
      logical, intent(in) :: eligible(:)
      integer(ip), intent(in) :: ngp
      integer(ip), intent(out) :: mate(:)
      integer(ip), allocatable :: start(:), list(:), fill(:), nb(:, :), deg(:), stack(:)
      integer(ip) :: n, i, j, k, e, a, b, top, u, best
      n = size(eligible)
      mate = 0
      if (n == 0) return
      ! gridpoint -> eligible zones (CSR)
      allocate (start(ngp + 1), fill(ngp))
      start = 0
      do i = 1, n
         if (.not. eligible(i)) cycle
         do k = 1, 3
            start(v(k, i) + 1) = start(v(k, i) + 1) + 1
         end do
      end do
      call counts_to_starts(start)
      allocate (list(max(1_ip, start(ngp + 1) - 1)))
      fill = start(1:ngp)
      do i = 1, n
         if (.not. eligible(i)) cycle
         do k = 1, 3
            list(fill(v(k, i))) = i
            fill(v(k, i)) = fill(v(k, i)) + 1
         end do
      end do
      ! neighbour across each edge (k, k+1)
      allocate (nb(3, n), deg(n))
      nb = 0
      deg = 0
      do i = 1, n
         if (.not. eligible(i)) cycle
         do e = 1, 3
            a = v(e, i)
            b = v(mod(e, 3) + 1, i)
            do k = start(a), start(a + 1) - 1
               j = list(k)
               if (j == i) cycle
               if (any(v(:, j) == b)) then
                  nb(e, i) = j
                  deg(i) = deg(i) + 1
                  exit
               end if
            end do
         end do
      end do
      ! greedy matching, zones with one choice first
      allocate (stack(n))
      top = 0
      do i = 1, n
         if (deg(i) == 1) call push(i)
      end do
      do i = 1, n
         call drain()
         if (.not. eligible(i) .or. mate(i) /= 0 .or. deg(i) == 0) cycle
         best = 0
         do e = 1, 3
            u = nb(e, i)
            if (u == 0) cycle
            if (mate(u) /= 0) cycle
            if (best == 0) then
               best = u
            else if (deg(u) < deg(best)) then
               best = u
            end if
         end do
         if (best > 0) call pair(i, best)
         call drain()
      end do
      ! leftovers: one way to a matched neighbour
      do i = 1, n
         if (.not. eligible(i) .or. mate(i) /= 0) cycle
         do e = 1, 3
            if (nb(e, i) > 0) then
               mate(i) = nb(e, i)
               exit
            end if
         end do
      end do
   contains
      subroutine push(z)
         integer(ip), intent(in) :: z
         top = top + 1               ! each zone is pushed at most once: its degree
         stack(top) = z              ! only falls, and reaches 1 once
      end subroutine push

      subroutine pair(p, q)
         integer(ip), intent(in) :: p, q
         integer(ip) :: m, w, zz, y
         mate(p) = q
         mate(q) = p
         do m = 1, 2
            zz = p
            if (m == 2) zz = q
            do w = 1, 3
               y = nb(w, zz)
               if (y == 0) cycle
               if (mate(y) /= 0) cycle
               deg(y) = deg(y) - 1
               if (deg(y) == 1) call push(y)
            end do
         end do
      end subroutine pair

      subroutine drain()
         integer(ip) :: z, w, q
         do while (top > 0)
            z = stack(top)
            top = top - 1
            if (mate(z) /= 0) cycle
            q = 0
            do w = 1, 3
               if (nb(w, z) == 0) cycle
               if (mate(nb(w, z)) == 0) then
                  q = nb(w, z)
                  exit
               end if
            end do
            if (q > 0) call pair(z, q)
         end do
      end subroutine drain
   end subroutine zone_partners
end module zones_mixed
