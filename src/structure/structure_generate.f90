!> STRUCTURE xc yc fang rrange npoin mat thick <ang> (manual Section 4.5):
!> npoin beam elements along the periphery of an opening around (xc, yc).
!>
!> Node k lies where the ray from (xc, yc) at angle fang + k ang / npoin
!> (degrees, counter-clockwise; ang = 360 by default, a closed ring of npoin
!> nodes; otherwise an open arc of npoin + 1 nodes) first meets a block edge
!> facing the centre within the distance rrange. Each node gets an interface
!> with that block edge; consecutive nodes are joined by elements. Element and
!> interface material are both `mat` (manual note). Nothing changes unless
!> every ray finds its edge.
module structure_generate
   use core_constants, only: pi
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: format_real, itoa
   use model_geometry, only: geometry_t
   use model_structures, only: structure_t, structure_add_node, structure_add_element, &
                               structure_add_interface
   implicit none
   private
   public :: structure_build


contains

   subroutine structure_build(st, geo, xc, yc, fang, rrange, npoin, mat, thick, ang, error)
      type(structure_t), intent(inout) :: st
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: xc, yc, fang, rrange, thick, ang
      integer(ip), intent(in) :: npoin, mat
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: nnode, k, b, c, cn, id, first, prev, nb(1)
      integer(ip), allocatable :: hit_block(:), hit_edge(:)
      real(wp), allocatable :: hx(:), hy(:), hnx(:), hny(:)
      real(wp) :: a, dx, dy, best, ex, ey, den, t, u, nx, ny, l
      real(wp) :: utol
      logical :: closed
      if (rrange <= 0.0_wp) then
         call set_error(error, 'STRUCTURE: rrange must be > 0 (the search radius around xc yc)')
         return
      end if
      if (abs(ang) <= 0.0_wp) then
         call set_error(error, 'STRUCTURE: ang must not be 0')
         return
      end if
      closed = abs(ang) >= 360.0_wp - 1.0e-9_wp
      nnode = npoin
      if (.not. closed) nnode = npoin + 1
      if (nnode < 2 .or. (closed .and. npoin < 3)) then
         call set_error(error, 'STRUCTURE: need npoin >= 3 for a closed ring')
         return
      end if
      allocate (hit_block(nnode), hit_edge(nnode), hx(nnode), hy(nnode), hnx(nnode), hny(nnode))
      associate (bl => geo%blocks, co => geo%corners)
         do k = 1, nnode
            a = (fang + ang*real(k - 1, wp)/real(npoin, wp))*pi/180.0_wp
            dx = cos(a)
            dy = sin(a)
            best = huge(1.0_wp)
            hit_block(k) = 0
            do b = 1, bl%n
               if (.not. bl%live(b)) cycle
               c = bl%first_corner(b)
               do while (.true.)
                  cn = co%next(c)
                  ex = co%x(cn) - co%x(c)
                  ey = co%y(cn) - co%y(c)
                  l = hypot(ex, ey)
                  ! outward normal (clockwise ring: block on the right)
                  nx = -ey/l
                  ny = ex/l
                  den = dx*ey - dy*ex
                  if (nx*dx + ny*dy < 0.0_wp .and. abs(den) > 0.0_wp) then
                     ! xc + t d = c + u e
                     t = ((co%x(c) - xc)*ey - (co%y(c) - yc)*ex)/den
                     u = ((co%x(c) - xc)*dy - (co%y(c) - yc)*dx)/den
                     ! a ray through the end of a joint on the periphery meets
                     ! the two blocks' edges there at u = 0 and 1 give or take
                     ! rounding, or passes through the joint's gap between
                     ! their corners: within the corners' rounding length
                     ! it takes the nearer edge rather than missing both
                     utol = max(1.0e-9_wp, co%radius(c)/l, co%radius(cn)/l)
                     if (t >= 0.0_wp .and. t <= rrange .and. u >= -utol .and. u <= 1.0_wp + utol &
                         .and. t < best) then
                        best = t
                        hit_block(k) = b
                        hit_edge(k) = c
                        hx(k) = xc + t*dx
                        hy(k) = yc + t*dy
                        hnx(k) = nx
                        hny(k) = ny
                     end if
                  end if
                  c = cn
                  if (c == bl%first_corner(b)) exit
               end do
            end do
            if (hit_block(k) == 0) then
               call set_error(error, 'STRUCTURE: no block edge facing ('//format_real(xc)// &
                              ', '//format_real(yc)//') within rrange '//format_real(rrange)// &
                              ' along the angle '//format_real(a*180.0_wp/pi)// &
                              ' degrees (node '//itoa(k)//'); nothing was created')
               return
            end if
         end do
      end associate
      do k = 2, nnode + merge(1, 0, closed)
         b = k
         if (k > nnode) b = 1
         if (hypot(hx(b) - hx(k - 1), hy(b) - hy(k - 1)) <= max(geo%tol, 1.0e-12_wp)) then
            call set_error(error, 'STRUCTURE: nodes '//itoa(k - 1)//' and '// &
                           itoa(b)//' fall on the same point; nothing was created')
            return
         end if
      end do
      nb = 0
      first = 0
      prev = 0
      do k = 1, nnode
         call structure_add_node(st, hx(k), hy(k), mat, id)
         if (k == 1) first = id
         if (k > 1) call structure_add_element(st, prev, id, mat, thick, nb(1))
         call structure_add_interface(st, id, hit_block(k), hit_edge(k), mat, hx(k), hy(k), &
                                      hnx(k), hny(k), nb(1))
         prev = id
      end do
      if (closed) call structure_add_element(st, prev, first, mat, thick, nb(1))
   end subroutine structure_build

end module structure_generate
