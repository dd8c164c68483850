!> GENERATE (manual Section 4.5): zone the blocks whose centroid lies in the
!> range (all blocks without a range) into constant-strain triangles and
!> make them fully deformable. AUTO / EDGE edmax, QUAD xw <yw>, MANUAL
!> GRIDPOINT x y ... ZONE l m n ... (docs/zones.md). Every block is zoned
!> in memory first; the model changes only when all of them succeeded.
module commands_zones
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_interrupt, only: interrupt_pending
   use core_output, only: output_t, fmt_real
   use model_state, only: model_t
   use model_geometry, only: geometry_block_polygon
   use geometry_polygon, only: point_in_polygon, polygon_boundary_distance
   use zones_mesh, only: mesh_t, mesh_auto, mesh_quad, mesh_manual, mesh_sharpest_zone, &
                         mesh_smallest_zone
   use zones_generate, only: zones_apply_mesh
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t, warn_fdef_free
   use commands_geometry, only: remove_partial_cracks_once, boundary_condition_corners
   implicit none
   private
   public :: register_zone_commands
   public :: do_generate

   real(wp), parameter :: max_zones = 5.0e7_wp

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_zone_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('zones', 'GEnerate', '[R]', '', 'Edge p;AUto p;Quad p[p];Manual;' // &
                   'Gridpoint r*;Zone q*', '4.5', &
                   'zone fully deformable blocks into triangles', handler=do_generate)
      call reg%note('EDGE AUTO QUAD', unit='m')
   end subroutine register_zone_commands

   subroutine do_generate(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k, kauto, kquad, kman, ng, nzv, j
      integer(ip) :: b, nsel, i, nz, ngp, nfixed
      integer(ip), allocatable :: sel(:), bc_corner(:)
      type(mesh_t), allocatable :: meshes(:)
      real(wp), allocatable :: x(:), y(:), gx(:), gy(:)
      integer, allocatable :: zl(:)
      real(wp) :: edmax, xw, yw, amin, mx, my, ang, xa, ya, za, xmin, ymin, zmin, atotal
      integer(ip) :: bmin, nedge, bedge
      character(len=:), allocatable :: why
      !> zone angle (degrees) below which GENERATE names the block: a needle
      real(wp), parameter :: needle_zone_angle = 2.0_wp
      !> zone edges on block edges shorter than this fraction of ROUND are named
      real(wp), parameter :: short_edge_fraction = 0.5_wp
      type(error_t), allocatable :: err
      character(len=600) :: text

      associate (model => ctx%model, out => ctx%out)
         associate (geo => model%geometry)
            if (.not. geo%block_created) then
               call set_error(error, 'GENERATE: no BLOCK has been created')
               return
            end if
            if (geo%mechanical) then
               call set_error(error, 'GENERATE: blocks must be zoned before the first CYCLE ' &
                              //'(CYCLE 0 included) and before INSITU loads the joints: contacts ' &
                              //'then carry state tied to the corners that zoning renumbers')
               return
            end if
            kauto = parsed%find('AUTO')
            if (kauto == 0) kauto = parsed%find('EDGE')
            kquad = parsed%find('QUAD')
            kman = parsed%find('MANUAL')
            if (parsed%count_of([character(len=6) :: 'AUTO', 'EDGE', 'QUAD', &
                                 'MANUAL']) /= 1) then
               call set_error(error, 'GENERATE: give exactly one of AUTO edmax, EDGE edmax, ' &
                              //'QUAD xw <yw> or MANUAL GRIDPOINT ... ZONE ...')
               return
            end if
            ! gridpoint and zone lists of MANUAL (possibly several GRID / ZONE items)
            ng = 0
            nzv = 0
            allocate (gx(0), gy(0), zl(0))
            do k = 1, parsed%nitems
               select case (parsed%items(k)%name)
               case ('GRIDPOINT')
                  if (mod(parsed%items(k)%count, 2) /= 0) then
                     call set_error(error, 'GENERATE GRIDPOINT: expected x y pairs')
                     return
                  end if
                  do j = 1, parsed%items(k)%count/2
                     gx = [gx, parsed%real_at(k, 2*j - 1)]
                     gy = [gy, parsed%real_at(k, 2*j)]
                  end do
               case ('ZONE')
                  do j = 1, parsed%items(k)%count
                     zl = [zl, parsed%int_at(k, j)]
                  end do
               end select
            end do
            ng = size(gx)
            nzv = size(zl)
            if (kman == 0 .and. (ng > 0 .or. nzv > 0)) then
               call set_error(error, 'GENERATE: GRIDPOINT and ZONE belong to MANUAL')
               return
            end if
            if (kman > 0) then
               if (ng < 3 .or. nzv < 3 .or. mod(nzv, 3) /= 0) then
                  call set_error(error, 'GENERATE MANUAL: expected GRIDPOINT x1 y1 x2 y2 ... ' &
                                 //'(3 or more) and ZONE l1 m1 n1 ... (triples)')
                  return
               end if
            end if

            ! the blocks to zone
            allocate (sel(geo%blocks%n))
            nsel = 0
            do b = 1, geo%blocks%n
               if (.not. geo%blocks%live(b)) cycle
               if (.not. parsed%range%contains_point(geo%blocks%xc(b), geo%blocks%yc(b))) cycle
               nsel = nsel + 1
               sel(nsel) = b
            end do
            if (kman > 0) then
               ! MANUAL zones one block: the one (in range) holding the gridpoints' mean
               mx = sum(gx)/ng
               my = sum(gy)/ng
               j = 0
               do i = 1, nsel
                  call geometry_block_polygon(geo, sel(i), x, y)
                  if (point_in_polygon(x, y, mx, my) .or. &
                      polygon_boundary_distance(x, y, mx, my) <= geo%tol) then
                     j = j + 1
                     sel(1) = sel(i)
                     exit
                  end if
               end do
               nsel = j
               if (nsel == 0) then
                  call set_error(error, 'GENERATE MANUAL: no block (in range) contains the ' &
                                 //'gridpoints')
                  return
               end if
            end if
            if (nsel == 0) then
               call out%line('GENERATE: no block has its centroid in the range; nothing zoned')
               return
            end if
            ! blocks already zoned are left as they are: a fine GEN in a range
            ! round the opening, then GEN without a range for the rest, is how
            ! a user zones a jointed model whose blocks straddle any range
            ! (random tunnels: "block 3 is already zoned" stopped such decks)
            if (kman > 0 .and. geo%blocks%nzone(sel(1)) > 0) then
               write (text, '(a,i0,a)') 'GENERATE MANUAL: block ', sel(1), ' is already zoned'
               call set_error(error, trim(text))
               return
            end if
            j = 0
            do i = 1, nsel
               if (geo%blocks%nzone(sel(i)) > 0) cycle
               j = j + 1
               sel(j) = sel(i)
            end do
            if (j < nsel) then
               write (text, '(a,i0,a)') 'Note: GENERATE: ', nsel - j, &
                  ' block(s) in the range already zoned, left as they are'
               call out%line(trim(text))
            end if
            nsel = j
            if (nsel == 0) then
               call out%line('GENERATE: every block in the range is already zoned; nothing zoned')
               return
            end if

            ! a mistyped edmax (1e-30) would take hours: estimate the zone count
            if (kauto > 0 .or. kquad > 0) then
               edmax = parsed%real_at(max(kauto, kquad), 1)
               if (kquad > 0) then
                  if (parsed%items(kquad)%count > 1) edmax = sqrt(edmax*parsed%real_at(kquad, 2))
               end if
               mx = 0.0_wp
               do i = 1, nsel
                  mx = mx + geo%blocks%area(sel(i))
               end do
               if (mx/(0.4_wp*edmax**2) > max_zones) then
                  call set_error(error, 'GENERATE: this zone size would create more than ' &
                                 //'50 million zones')
                  return
               end if
            end if

            ! zone every block in memory
            allocate (meshes(nsel))
            nedge = 0
            bedge = 0
            do i = 1, nsel
               b = sel(i)
               ! Ctrl-C / SIGTERM: stop before anything is applied
               if (interrupt_pending()) then
                  write (text, '(a,i0,a,i0,a)') 'GENERATE interrupted while zoning block ', i, &
                     ' of ', nsel, ': nothing was zoned'
                  call set_error(error, trim(text))
                  return
               end if
               call geometry_block_polygon(geo, b, x, y)
               if (kauto > 0) then
                  edmax = parsed%real_at(kauto, 1)
                  call mesh_auto(x, y, edmax, meshes(i), err)
               else if (kquad > 0) then
                  xw = parsed%real_at(kquad, 1)
                  yw = xw
                  if (parsed%items(kquad)%count > 1) yw = parsed%real_at(kquad, 2)
                  call mesh_quad(x, y, xw, yw, meshes(i), err)
                  if (allocated(err)) then
                     ! A jointed model is mostly triangles and pentagons: QUAD zones
                     ! its quadrilaterals and the rest with EDGE at the same size
                     ! rather than refusing the whole model for one triangle.
                     nedge = nedge + 1
                     if (nedge == 1) then
                        bedge = b
                        why = err%message
                     end if
                     deallocate (err)
                     call mesh_auto(x, y, sqrt(xw*yw), meshes(i), err)
                  end if
               else
                  call mesh_manual(x, y, gx, gy, zl, 0.9_wp*geo%round, meshes(i), err)
               end if
               if (allocated(err)) then
                  write (text, '(a,i0,a)') 'GENERATE: block ', b, ': '
                  call set_error(error, trim(text)//' '//err%message)
                  return
               end if
            end do

            ! BOUNDARY conditions are forces per corner: a block whose ring gets new
            ! corners would lose them silently (the old corners die)
            bc_corner = boundary_condition_corners(model)
            do i = 1, nsel
               b = sel(i)
               if (meshes(i)%nb == geo%blocks%ncorner(b)) cycle
               j = bc_corner(b)
               if (j > 0) then
                  write (text, '(a,i0,a,i0,a)') 'GENERATE: block ', b, &
                     ' carries conditions of an ' &
                     //'earlier BOUNDARY command (corner ', j, '); zoning adds corners to its ' &
                     //'edges and the conditions would be lost: give GENERATE before BOUNDARY'
                  call set_error(error, trim(text))
                  return
               end if
            end do

            ! apply
            call remove_partial_cracks_once(model, out)
            nz = 0
            ngp = 0
            amin = 180.0_wp
            bmin = 0
            atotal = 0.0_wp
            nfixed = 0
            do i = 1, nsel
               ! FDEF blocks cannot be fixed (manual Section 4.5, FIX)
               if (geo%blocks%fixed(sel(i))) nfixed = nfixed + 1
               geo%blocks%fixed(sel(i)) = .false.
               call zones_apply_mesh(geo, sel(i), meshes(i))
               nz = nz + meshes(i)%nt
               ngp = ngp + meshes(i)%np
               atotal = atotal + geo%blocks%area(sel(i))
               call mesh_sharpest_zone(meshes(i), ang, xa, ya, za)
               if (ang < amin) then
                  amin = ang
                  bmin = sel(i)
                  xmin = xa
                  ymin = ya
                  zmin = za
               end if
            end do
            write (text, '(a,i0,a,i0,a,i0,a,f0.1,a)') 'GENERATE: ', nsel, ' block(s) zoned, ', nz, &
               ' zones, ', ngp, ' gridpoints, smallest zone angle ', amin, ' degrees'
            call out%line(trim(text))
            call note_many_zones()
            if (nedge > 0) then
               write (text, '(a,i0,a,i0,a,i0,a,es9.3,a)') 'Note: GENERATE QUAD: ', nedge, &
                  ' of the ', nsel, ' block(s) (the first: block ', bedge, &
                  ') are not convex quadrilaterals ('//why//'): zoned as by EDGE ', sqrt(xw*yw), &
                  ' (triangles without QUAD''s crossed diagonals, which Section 4.5 advises ' &
                  //'for Mohr-Coulomb zones)'
               call out%line(trim(text))
            end if
            if (nfixed > 0) call warn_fdef_free(out, 'GENERATE', nfixed, &
                                                ' FIXed block(s) zoned and so released')
            ! A needle corner (a cut meeting an edge at a shallow angle, a tunnel
            ! nearly tangent to a joint) gets zones far smaller than the rest, and
            ! the smallest zone sets the time step of the whole model.
            if (bmin > 0 .and. amin < needle_zone_angle .and. nz > 0) then
               write (text, '(a,i0,a,f0.1,a,es10.3,a,es10.3,a,es9.2,a,es9.2,a)') &
                  'Warning: GENERATE: block ', bmin, ' has a zone angle of ', amin, &
                  ' degrees at (', xmin, ',', ymin, '), a zone of ', zmin, &
                     ' m2 where the mean is ', &
                  atotal/real(nz, wp), ' m2: its zones set the time step; a needle-shaped corner ' &
                  //'of the block (PRINT CORNERS), left where a cut meets an edge at a shallow ' &
                  //'angle; moving that joint or tunnel slightly removes it'
               call out%line(trim(text))
            else if (nz > 0) then
               call warn_small_zone()
            end if
            call warn_short_edges()
         end associate
      end associate
   contains
      !> A model zoned so finely that a static solution takes hours: a new
      !> user's GEN EDGE 0.05 in a 20 m square (round 12, docs/closed_form.md)
      !> made 418 863 zones without a word, and its CYCLE 10 took 17 s (a
      !> SOLVE of a jointed tunnel takes thousands of cycles).
      subroutine note_many_zones()
         !> zones in the model above which GENERATE says what a SOLVE costs
         integer(ip), parameter :: many_zones = 200000
         integer(ip) :: nlive
         nlive = count(ctx%model%geometry%zones%live(1:ctx%model%geometry%zones%n))
         if (nlive < many_zones) return
         write (text, '(a,i0,a)') 'Note: GENERATE: the model now has ', nlive, ' zones: every '// &
            'cycle works on every zone and a static SOLVE takes thousands of cycles, so expect '// &
            'hours; a few zones across each block (a larger EDGE, finer only near the opening: '// &
            'GENERATE range EDGE) gives the answer at a fraction of the cost'
         call ctx%out%line(trim(text))
      end subroutine note_many_zones

      !> A zone far smaller than the mean one, not needle-shaped (a sliver
      !> between a joint and the model's side at a few degrees: the campaign's
      !> seed 6, zones of 2.6e-7 m2 where the mean is 7.8e-4, smallest angle
      !> 2.0 degrees) sets the time step of the whole model all the same: say
      !> so, with the remedy for a static solution.
      subroutine warn_small_zone()
         !> below this fraction of the mean zone area (a step about 20 times
         !> shorter than the mean zone's), GENERATE names the zone
         real(wp), parameter :: small_zone_fraction = 1.0_wp/500.0_wp
         integer(ip) :: i, bsmall
         real(wp) :: a, asmall, xs, ys, xa, ya
         asmall = huge(1.0_wp)
         bsmall = 0
         xs = 0.0_wp
         ys = 0.0_wp
         do i = 1, nsel
            call mesh_smallest_zone(meshes(i), a, xa, ya)
            if (a < asmall) then
               asmall = a
               bsmall = sel(i)
               xs = xa
               ys = ya
            end if
         end do
         if (bsmall == 0 .or. .not. asmall < small_zone_fraction*atotal/real(nz, wp)) return
         write (text, '(a,i0,7a,i0,5a)') 'Warning: GENERATE: block ', bsmall, ' has a zone of ', &
            trim(adjustl(fmt_real(asmall, 10, 3))), ' m2 at (', trim(adjustl(fmt_real(xs, 11, 4))), &
            ', ', trim(adjustl(fmt_real(ys, 11, 4))), '), 1/', &
            nint(min(1.0e9_wp, atotal/real(nz, wp)/max(asmall, tiny(1.0_wp)))), ' of the mean zone (', &
            trim(adjustl(fmt_real(atotal/real(nz, wp), 10, 3))), ' m2): it sets the time step of ' &
            //'the whole model (a sliver where a joint meets an edge at a small angle); for a ' &
            //'static solution MSCALE ON (manual Section 4.5) takes that cost away, or move the ' &
            //'joint slightly'
         call ctx%out%line(trim(text))
      end subroutine warn_small_zone

      !> Zones along a block's edge much shorter than ROUND (a sliver's
      !> needle, zoned finely) sit under a neighbour's rounded corner, whose
      !> one contact spans several of their gridpoints and puts its force on
      !> the one at its vertex (contact_side). Found on a new user's model
      !> (bedding at 2.7 degrees meeting the top boundary, ROUND 0.1, edges
      !> of 0.03 m): the needle rang and tore off after an excavation, which
      !> contact_side no longer lets happen (stability.needle_excavation);
      !> the warning stays, since the user may prefer a rounding that gives
      !> each gridpoint its own contact.
      subroutine warn_short_edges()
         integer(ip) :: nshort, bshort, c, q, k
         real(wp) :: lmin, xs, ys, l
         nshort = 0
         bshort = 0
         lmin = huge(1.0_wp)
         xs = 0.0_wp
         ys = 0.0_wp
         associate (geo => ctx%model%geometry)
            do i = 1, nsel
               b = sel(i)
               c = geo%blocks%first_corner(b)
               do k = 1, geo%blocks%ncorner(b)
                  q = geo%corners%next(c)
                  l = hypot(geo%corners%x(q) - geo%corners%x(c), geo%corners%y(q) - geo%corners%y(c))
                  if (l < short_edge_fraction*geo%round) then
                     nshort = nshort + 1
                     if (l < lmin) then
                        lmin = l
                        bshort = b
                        xs = 0.5_wp*(geo%corners%x(q) + geo%corners%x(c))
                        ys = 0.5_wp*(geo%corners%y(q) + geo%corners%y(c))
                     end if
                  end if
                  c = q
               end do
            end do
            if (nshort == 0) return
            write (text, '(a,i0,a,es9.2,a,es9.2,a,i0,a,es10.3,a,es10.3,a)') &
               'Warning: GENERATE: ', nshort, ' zone edge(s) on block edges are shorter than ' &
               //'half of ROUND (', geo%round, ' m); the shortest, ', lmin, ' m, is on block ', &
               bshort, ' at (', xs, ',', ys, '): a neighbour''s rounded corner spans several ' &
               //'of their gridpoints and puts its force on the one at its vertex; a ROUND ' &
               //'below twice that length (ROUND comes before BLOCK), or moving the joint that ' &
               //'makes the sliver, gives each its own contact'
            call ctx%out%line(trim(text))
         end associate
      end subroutine warn_short_edges
   end subroutine do_generate


end module commands_zones
