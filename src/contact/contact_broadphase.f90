!> Broad phase of contact detection: the pairs of blocks whose bounding
!> boxes, enlarged by `g`, overlap. A uniform grid of cells about the mean
!> block size; each block is entered in the cells its box covers, and a pair
!> is reported only by the cell holding the lower-left corner of the overlap
!> of the two boxes, so each pair is seen once and the cost is O(blocks).
module contact_broadphase
   use core_arrays, only: grow_array
   use core_kinds, only: wp, ip
   use model_geometry, only: geometry_t
   implicit none
   private
   public :: broadphase_pairs, update_bounding_boxes

contains

   !> Bounding boxes of live blocks from their current corners.
   subroutine update_bounding_boxes(geo)
      type(geometry_t), intent(inout) :: geo
      integer(ip) :: b, k, c
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         c = geo%blocks%first_corner(b)
         geo%blocks%xmin(b) = geo%corners%x(c); geo%blocks%xmax(b) = geo%corners%x(c)
         geo%blocks%ymin(b) = geo%corners%y(c); geo%blocks%ymax(b) = geo%corners%y(c)
         do k = 2, geo%blocks%ncorner(b)
            c = geo%corners%next(c)
            geo%blocks%xmin(b) = min(geo%blocks%xmin(b), geo%corners%x(c))
            geo%blocks%xmax(b) = max(geo%blocks%xmax(b), geo%corners%x(c))
            geo%blocks%ymin(b) = min(geo%blocks%ymin(b), geo%corners%y(c))
            geo%blocks%ymax(b) = max(geo%blocks%ymax(b), geo%corners%y(c))
         end do
      end do
   end subroutine update_bounding_boxes

   !> Pairs (pa(k) < pb(k), k = 1..npair) of live blocks within `g`.
   subroutine broadphase_pairs(geo, g, npair, pa, pb)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: g
      integer(ip), intent(out) :: npair
      integer(ip), allocatable, intent(inout) :: pa(:), pb(:)
      real(wp) :: x0, y0, x1, y1, h, sz, ox, oy
      integer(ip) :: nb, b, nx, ny, i, j, k, ix0, ix1, iy0, iy1, ncell, cell, p, q, bi, bj
      integer(ip), allocatable :: start(:), fill(:), members(:)
      npair = 0
      if (.not. allocated(pa)) allocate (pa(64), pb(64))
      nb = 0
      sz = 0.0_wp
      x0 = huge(1.0_wp); y0 = huge(1.0_wp); x1 = -huge(1.0_wp); y1 = -huge(1.0_wp)
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         nb = nb + 1
         sz = sz + max(geo%blocks%xmax(b) - geo%blocks%xmin(b), &
                       geo%blocks%ymax(b) - geo%blocks%ymin(b))
         x0 = min(x0, geo%blocks%xmin(b)); x1 = max(x1, geo%blocks%xmax(b))
         y0 = min(y0, geo%blocks%ymin(b)); y1 = max(y1, geo%blocks%ymax(b))
      end do
      if (nb < 2) return
      x0 = x0 - 2.0_wp*g; y0 = y0 - 2.0_wp*g; x1 = x1 + 2.0_wp*g; y1 = y1 + 2.0_wp*g
      h = max(sz/real(nb, wp), g)
      ! a block thrown far away (or a non-finite position, which the cycle
      ! reports) must not make a grid whose cell count overflows an integer
      if (.not. (x1 - x0 <= huge(1.0_wp) .and. y1 - y0 <= huge(1.0_wp) .and. h > 0.0_wp)) return
      ! keep the grid no larger than a few cells per block (counted in reals
      ! so a huge extent cannot overflow the integer cell numbers)
      do
         if (((x1 - x0)/h + 1.0_wp)*((y1 - y0)/h + 1.0_wp) <= 4.0_wp*real(nb, wp) + 16.0_wp) exit
         h = 1.5_wp*h
      end do
      nx = int((x1 - x0)/h) + 1
      ny = int((y1 - y0)/h) + 1
      ncell = nx*ny
      allocate (start(ncell + 1), fill(ncell))
      start = 0
      call bin_blocks(.false.)
      start(1) = 1
      do cell = 1, ncell
         start(cell + 1) = start(cell + 1) + start(cell)
      end do
      allocate (members(start(ncell + 1) - 1))
      fill = start(1:ncell)
      call bin_blocks(.true.)
      do cell = 1, ncell
         i = modulo(cell - 1, nx) + 1
         j = (cell - 1)/nx + 1
         do p = start(cell), start(cell + 1) - 1
            do q = p + 1, start(cell + 1) - 1
               bi = min(members(p), members(q))
               bj = max(members(p), members(q))
               ! overlap of the two (gap-expanded) boxes
               if (geo%blocks%xmin(bi) > geo%blocks%xmax(bj) + g) cycle
               if (geo%blocks%xmin(bj) > geo%blocks%xmax(bi) + g) cycle
               if (geo%blocks%ymin(bi) > geo%blocks%ymax(bj) + g) cycle
               if (geo%blocks%ymin(bj) > geo%blocks%ymax(bi) + g) cycle
               ox = max(geo%blocks%xmin(bi), geo%blocks%xmin(bj)) - g
               oy = max(geo%blocks%ymin(bi), geo%blocks%ymin(bj)) - g
               k = (min(nx, max(1_ip, int((ox - x0)/h) + 1)) - i)**2 + &
                   (min(ny, max(1_ip, int((oy - y0)/h) + 1)) - j)**2
               if (k /= 0) cycle
               if (npair >= size(pa)) call grow_pairs(2*size(pa))
               npair = npair + 1
               pa(npair) = bi
               pb(npair) = bj
            end do
         end do
      end do
   contains
      !> Visit every cell each live block's (gap-expanded) box covers: count
      !> the blocks of each cell in start(cell + 1), or (`place`) put each
      !> block in its cells' stretch of members.
      subroutine bin_blocks(place)
         logical, intent(in) :: place
         integer(ip) :: blk, ci, cj, cl
         do blk = 1, geo%blocks%n
            if (.not. geo%blocks%live(blk)) cycle
            call cell_range(blk)
            do cj = iy0, iy1
               do ci = ix0, ix1
                  cl = (cj - 1)*nx + ci
                  if (place) then
                     members(fill(cl)) = blk
                     fill(cl) = fill(cl) + 1
                  else
                     start(cl + 1) = start(cl + 1) + 1
                  end if
               end do
            end do
         end do
      end subroutine bin_blocks

      subroutine cell_range(blk)
         integer(ip), intent(in) :: blk
         ix0 = min(nx, max(1_ip, int((geo%blocks%xmin(blk) - g - x0)/h) + 1))
         ix1 = min(nx, max(1_ip, int((geo%blocks%xmax(blk) + g - x0)/h) + 1))
         iy0 = min(ny, max(1_ip, int((geo%blocks%ymin(blk) - g - y0)/h) + 1))
         iy1 = min(ny, max(1_ip, int((geo%blocks%ymax(blk) + g - y0)/h) + 1))
      end subroutine cell_range
      subroutine grow_pairs(m)
         integer(ip), intent(in) :: m
         call grow_array(pa, npair, m)
         call grow_array(pb, npair, m)
      end subroutine grow_pairs
   end subroutine broadphase_pairs

end module contact_broadphase
