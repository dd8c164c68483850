!> Consistency checks of the block geometry, for tests and for a debug
!> command: simple clockwise blocks, areas adding up, contacts on every
!> shared edge with the right total length, two domains per contact,
!> domains tiling the voids.
module contact_checks
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: fmt_real
   use geometry_polygon, only: polygon_is_simple, polygon_signed_area, segment_along_line
   use model_geometry, only: geometry_t, geometry_block_polygon, geometry_total_area
   implicit none
   private
   public :: check_blocks, check_contacts, check_domains, shared_length

contains

   !> Every live block simple, clockwise, not too small; areas add up to the
   !> original area minus deleted area within `rtol` relative.
   subroutine check_blocks(geo, rtol, error)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: rtol
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: x(:), y(:)
      character(len=120) :: text
      integer(ip) :: b
      real(wp) :: a
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         call geometry_block_polygon(geo, b, x, y)
         a = -polygon_signed_area(x, y)
         if (.not. a > 0.0_wp) then
            write (text, '(a,i0,2a)') 'block ', b, ' not clockwise or empty, area ', &
               fmt_real(a, 12, 4)
            call set_error(error, trim(text))
            return
         end if
         if (abs(a - geo%blocks%area(b)) > 1.0e-9_wp*a) then
            write (text, '(a,i0,a)') 'block ', b, ' stored area differs from its polygon'
            call set_error(error, trim(text))
            return
         end if
         if (.not. polygon_is_simple(x, y, geo%tol)) then
            write (text, '(a,i0,a)') 'block ', b, ' is not a simple polygon'
            call set_error(error, trim(text))
            return
         end if
      end do
      a = geometry_total_area(geo) + geo%deleted_area
      if (abs(a - geo%original_area) > rtol*geo%original_area) then
         write (text, '(4a)') 'block areas sum to ', fmt_real(a, 24, 16), ' not ', &
            fmt_real(geo%original_area, 24, 16)
         call set_error(error, trim(text))
      end if
   end subroutine check_blocks

   !> Length along which blocks b1 and b2 share boundary (antiparallel
   !> collinear edges within `g`).
   function shared_length(geo, b1, b2, g) result(total)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: b1, b2
      real(wp), intent(in) :: g
      real(wp) :: total
      real(wp), allocatable :: x1(:), y1(:), x2(:), y2(:)
      integer(ip) :: i, j, i2, j2, n1, n2
      real(wp) :: li, ux, uy, sa, sb
      logical :: near
      call geometry_block_polygon(geo, b1, x1, y1)
      call geometry_block_polygon(geo, b2, x2, y2)
      n1 = size(x1)
      n2 = size(x2)
      total = 0.0_wp
      do i = 1, n1
         i2 = merge(1_ip, i + 1_ip, i == n1)
         li = hypot(x1(i2) - x1(i), y1(i2) - y1(i))
         ux = (x1(i2) - x1(i))/li; uy = (y1(i2) - y1(i))/li
         do j = 1, n2
            j2 = merge(1_ip, j + 1_ip, j == n2)
            call segment_along_line(x1(i), y1(i), ux, uy, x2(j), y2(j), x2(j2), y2(j2), g, &
                                    near, sa, sb)
            if (.not. near) cycle
            total = total + max(0.0_wp, min(li, max(sa, sb)) - max(0.0_wp, min(sa, sb)))
         end do
      end do
   end function shared_length

   !> Every pair of blocks sharing an edge has contacts whose lengths add up
   !> to the shared length; every contact has a unit normal. Brute force over
   !> pairs with overlapping boxes: for tests of modest size.
   subroutine check_contacts(geo, error)
      type(geometry_t), intent(in) :: geo
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: plen(:)
      integer(ip) :: b1, b2, c, nb
      integer(ip), allocatable :: first(:), nxt(:)
      real(wp) :: s, g
      character(len=120) :: text
      nb = geo%blocks%n
      g = 10.0_wp*geo%tol
      allocate (first(nb), nxt(geo%contacts%n), plen(nb))
      ! contacts of each block1, as linked lists
      first = 0
      do c = geo%contacts%n, 1, -1
         if (.not. geo%contacts%live(c)) cycle
         if (abs(hypot(geo%contacts%nx(c), geo%contacts%ny(c)) - 1.0_wp) > 1.0e-9_wp) then
            write (text, '(a,i0,a)') 'contact ', c, ' normal is not a unit vector'
            call set_error(error, trim(text))
            return
         end if
         nxt(c) = first(geo%contacts%block1(c))
         first(geo%contacts%block1(c)) = c
      end do
      do b1 = 1, nb
         if (.not. geo%blocks%live(b1)) cycle
         plen = 0.0_wp
         c = first(b1)
         do while (c > 0)
            plen(geo%contacts%block2(c)) = plen(geo%contacts%block2(c)) + geo%contacts%length(c)
            c = nxt(c)
         end do
         do b2 = b1 + 1, nb
            if (.not. geo%blocks%live(b2)) cycle
            if (geo%blocks%xmin(b1) > geo%blocks%xmax(b2) + g) cycle
            if (geo%blocks%xmin(b2) > geo%blocks%xmax(b1) + g) cycle
            if (geo%blocks%ymin(b1) > geo%blocks%ymax(b2) + g) cycle
            if (geo%blocks%ymin(b2) > geo%blocks%ymax(b1) + g) cycle
            s = shared_length(geo, b1, b2, g)
            if (abs(s - plen(b2)) > 1.0e-7_wp*max(1.0_wp, s)) then
               write (text, '(a,i0,a,i0,4a)') 'blocks ', b1, ' and ', b2, &
                  ' share ', fmt_real(s, 12, 4), ' but contacts cover ', fmt_real(plen(b2), 12, 4)
               call set_error(error, trim(text))
               return
            end if
         end do
      end do
   end subroutine check_contacts

   !> Every contact has two domains; the domain areas add up to minus the
   !> area of the blocks that have contacts; voids are not negative.
   subroutine check_domains(geo, error)
      type(geometry_t), intent(in) :: geo
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: has(:)
      integer(ip) :: c, d
      real(wp) :: ablocks, adom, scale
      character(len=120) :: text
      allocate (has(geo%blocks%n))
      has = .false.
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         if (geo%contacts%dom1(c) <= 0 .or. geo%contacts%dom2(c) <= 0) then
            write (text, '(a,i0,a)') 'contact ', c, ' lacks a domain'
            call set_error(error, trim(text))
            return
         end if
         has(geo%contacts%block1(c)) = .true.
         has(geo%contacts%block2(c)) = .true.
      end do
      ablocks = 0.0_wp
      do c = 1, geo%blocks%n
         if (geo%blocks%live(c) .and. has(c)) ablocks = ablocks + geo%blocks%area(c)
      end do
      adom = 0.0_wp
      scale = max(geo%original_area, 1.0e-30_wp)
      do d = 1, geo%domains%n
         if (.not. geo%domains%live(d)) cycle
         adom = adom + geo%domains%area(d)
         if (.not. geo%domains%outer(d) .and. geo%domains%area(d) < -1.0e-9_wp*scale) then
            write (text, '(a,i0,2a)') 'domain ', d, ' has negative area ', &
               fmt_real(geo%domains%area(d), 12, 4)
            call set_error(error, trim(text))
            return
         end if
      end do
      if (abs(adom + ablocks) > 1.0e-9_wp*scale) then
         write (text, '(4a)') 'domain areas sum to ', fmt_real(adom, 16, 8), &
            ' not minus block area ', fmt_real(ablocks, 16, 8)
         call set_error(error, trim(text))
      end if
   end subroutine check_domains

end module contact_checks
