!> Geometry commands (manual Sections 4.2 II, 4.5): BLOCK, ROUND, EDGE, SPLIT,
!> CRACK, JDELETE, JREGION, JSET, TUNNEL, ARC, DELETE, UPCON, UPDOM, and the
!> geometry part of SET (PRINT is in commands_print). Handlers check what the parser cannot, then
!> call the geometry engine, which rejects a bad cut without changing the model.
module commands_geometry
   use commands_address, only: resolve_entity
   use engine_history, only: history_reattach
   use model_history, only: hist_keyword
   use model_address, only: ak_block
   use core_kinds, only: wp, ip, i8
   use core_constants, only: pi
   use core_error, only: error_t, set_error
   use core_interrupt, only: interrupt_pending
   use core_output, only: output_t, format_real, fmt_real, itoa
   use model_state, only: model_t
   use model_geometry, only: geometry_t, round_default, rjoint_file, geometry_set_seed, geometry_live_blocks, &
                             geometry_block_polygon, ncut_stats, cut_made, cut_snapped, &
                             cut_bend_moved, cut_refused_short, cut_refused_sliver, &
                             cut_refused_shape, cut_sliver_merged, geometry_tol_rel
   use geometry_cutting, only: rjoint_traces, cut_create_block, cut_create_circular, cut_set_round, &
                              cut_set_edge, cut_split, cut_crack, cut_remove_partial, &
                              cut_delete_block, cut_segment_pieces, ring_polygon, &
                              cut_key_pending_loops
   use geometry_polygon, only: point_in_polygon, polygon_boundary_distance, polygon_signed_area, &
                               polygon_is_simple
   use geometry_joint_sets, only: joint_region, joint_set, joint_tunnel, joint_arc, ring_snap_reach, &
                                  ring_fit_t
   use contact_detection, only: contact_rebuild
   use contact_domains, only: domain_rebuild
   use contact_refresh, only: geometry_refresh
   use commands_parser, only: parsed_t, item_loose
   use commands_context, only: context_t, registry_t, cannot_fail, require_block
   use model_boundary, only: bc_free, bh_constant, boundary_has_traction
   implicit none
   private
   public :: register_geometry_commands
   public :: set_geometry_keyword
   public :: remove_partial_cracks_once
   public :: boundary_condition_corners

   !> Guards against input that would take hours or exhaust memory (a mistyped
   !> spacing of 1e-30 in JSET, a TUNNEL of 1e9 sides): such commands are
   !> rejected with an error instead of hanging the program. The sides of a
   !> circle (BLOCK CIRCULAR, TUNNEL, ARC): fitting each corner's rounding
   !> circle checks it against every edge of its block, so a block of n
   !> corners costs n^2 (a 2000-sided BLOCK CIRCULAR 0.65 s, 8000 sides 10 s;
   !> 100 000 sides, the limit until 2026-11-26, ran for hours); 5000 sides
   !> follow a circle within 2e-7 of its radius.
   integer, parameter :: max_polygon_sides = 5000
   real(wp), parameter :: max_jset_joints = 1.0e6_wp
   !> Joints a JSET may draw over its JREGION (most fall outside the blocks
   !> and cost only their random draws).
   real(wp), parameter :: max_jset_draws = 1.0e8_wp
   !> Largest coordinate or length BLOCK, SPLIT, CRACK, JREGION, TUNNEL, ARC take.
   real(wp), parameter :: max_coordinate = 1.0e15_wp

   !> What a cutting command (SPLIT, CRACK, JSET, TUNNEL, ARC) needs to guard
   !> FDEF blocks and blocks carrying BOUNDARY conditions, and to summarise its
   !> cuts: the model's counts before it, and a copy of the geometry when an
   !> FDEF block or a block with conditions is live.
   type :: cut_guard_t
      integer(ip) :: nlive0 = 0, npend0 = 0, stats0(ncut_stats) = 0
      !> TUNNEL: blocks its ring still crosses (cut_summary warns)
      integer(ip) :: nstraddle = 0
      !> the first blocks it still crosses, named by the warning
      integer(ip) :: straddlers(3) = 0
      !> TUNNEL: how far its opening departs from the ring drawn
      type(ring_fit_t) :: fit
      type(geometry_t), allocatable :: saved
      !> per block of `saved`: a corner carrying a BOUNDARY condition, else 0
      integer(ip), allocatable :: bc_corner(:)
   end type cut_guard_t

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_geometry_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('geometry', 'Block', '', 'rr', 'Material q;COnstitutive c;CIrcular rrrq', &
                   '4.5', 'create the first block from its corners (x y pairs) or as a circle', &
                   handler=run_block)
      call reg%note('MATERIAL CONSTITUTIVE', default='1')
      call reg%add('geometry', 'ROund', 'p', '', '', '4.5', &
                   'rounding length of block corners', handler=run_length, &
                   unit='m', default='0.5', args='d')
      call reg%add('geometry', 'EDge', 'p', '', '', '4.5', &
                   'shortest edge a cut may leave (at least twice the rounding)', &
                   handler=run_length, &
                   unit='m', default='twice the rounding length (1)', args='emin')
      call reg%add('geometry', 'SPlit', 'rrrr', '', '', '4.5', &
                   'cut every block the line through two points crosses', handler=run_cut, &
                   unit='m', args='x1 y1 x2 y2')
      call reg%add('geometry', 'CRack', 'rrrr', '', 'JREG', '4.5', &
                   'cut along the segment between two points', handler=run_cut, &
                   unit='m', args='x1 y1 x2 y2')
      call reg%add('geometry', 'JDelete', '', '', '', '4.5', &
                   'remove the partial cracks (joints that end inside a block)', &
                   handler=run_jdelete)
      call reg%add('geometry', 'JRegion', 'rrrrrrrr', '', '', '4.5', &
                   'the quadrilateral region to which the next JSET is limited', &
                   handler=run_jregion, unit='m', args='x1 y1 x2 y2 x3 y3 x4 y4')
      call reg%add('geometry', 'JSet', 'rrrrrrrr[rr[r]]', '', '', '4.5', &
                   'a joint set: angle, trace, gap and spacing with their deviations, origin', &
                   handler=run_cut, args='a(m) a(d) t(m) t(d) g(m) g(d) s(m) s(d) [x0 y0 [ad0]]')
      call reg%add('geometry', 'TUnnel', 'rrrq', '', '', '4.5', &
                   'cut a circular opening: centre, radius, number of sides', handler=run_cut, &
                   args='xc yc r n')
      call reg%add('geometry', 'Arc', 'rrrrrq', '', '', '4.5', &
                   'cut along a circular arc: centre, start point, angle, segments', &
                   handler=run_cut, args='xc yc xb yb theta npoin')
      call reg%add('geometry', 'DElete', '[R[n]]', '', 'Area n;Block q', '4.5', &
                   'delete blocks in a range, smaller than an area, or by id', handler=do_delete)
      call reg%note('AREA', unit='m^2')
      call reg%add('geometry', 'UPCON', '', '', '', '4.5', &
                   'rebuild the contacts (and domains) now', handler=run_rebuild)
      call reg%add('geometry', 'UPDOM', '', '', '', '4.5', 'rebuild the domains now', &
                   handler=run_rebuild)
      call reg%add_set('geometry', 'SEed i;Edge p;JMatdf q;JCondf c', set_geometry)
      call reg%note('EDGE', unit='m', default='twice the rounding length (1)')
      call reg%note('JMATDF', default='the material of a block beside the contact')
      call reg%note('JCONDF', default='2')
   end subroutine register_geometry_commands

   !> Coordinates (and radii) of the shape-making commands stay within
   !> max_coordinate: beyond it squared lengths overflow (SPLIT 0.5 0 0.5
   !> 1e300 stopped the Debug build on a floating-point trap, issue 20).
   subroutine check_coordinates(parsed, error)
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      k = parsed%beyond(max_coordinate)
      if (k > 0) call set_error(error, parsed%name//': the number '// &
                                trim(format_real(parsed%values(k)%r))// &
                                ' is too large for a coordinate or length (at most 1E+15)')
   end subroutine check_coordinates

   !> Before a cut: counts for the summary and, since cuts may not reach FDEF
   !> blocks (manual 4.5 CRACK, 5.2.1) nor replace the corners that hold an
   !> earlier BOUNDARY command's conditions, a copy to restore when one was
   !> touched.
   subroutine cut_begin(model, guard, keep)
      type(model_t), intent(in) :: model
      type(cut_guard_t), intent(out) :: guard
      !> keep the blocks as they are in any case (JSET: an interrupt puts them back)
      logical, intent(in) :: keep
      logical :: need
      associate (geo => model%geometry)
         if (geo%block_created) guard%nlive0 = geometry_live_blocks(geo)
         guard%stats0 = geo%cut_stats
         guard%npend0 = geo%pending%n
         need = keep
         if (geo%blocks%n > 0) then
            need = need .or. any(geo%blocks%fdef(1:geo%blocks%n) .and. geo%blocks%live(1:geo%blocks%n))
            if (model%bound%n > 0) then
               guard%bc_corner = boundary_condition_corners(model)
               need = need .or. any(guard%bc_corner > 0)
            end if
         end if
         if (need) then
            allocate (guard%saved)
            guard%saved = geo
         end if
      end associate
   end subroutine cut_begin

   !> After a cut: undo it with an error when it touched an FDEF block or
   !> replaced the corners of a block carrying BOUNDARY conditions (they are
   !> kept per corner, and the cut block's corners die: the loads would vanish
   !> without a word, as GENERATE's check says), else print the summary.
   !> `previewed`: the command's joints are only recorded while JPLOT is on
   !> (CRACK, JSET), so there is nothing to summarise; the other cuts note
   !> that JPLOT does not preview them.
   subroutine cut_finish(geo, name, guard, out, error, previewed)
      type(geometry_t), intent(inout) :: geo
      character(len=*), intent(in) :: name
      type(cut_guard_t), intent(in) :: guard
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(inout) :: error
      logical, intent(in) :: previewed
      integer(ip) :: touched
      character(len=320) :: text
      if (allocated(error)) then
         ! a JSET stopped by Ctrl-C / SIGTERM mid-way: its blocks as before
         if (allocated(guard%saved) .and. interrupt_pending()) geo = guard%saved
         return
      end if
      if (allocated(guard%saved)) then
         call block_touched(guard%saved, geo, guard%npend0, touched)
         if (touched > 0) then
            geo = guard%saved
            write (text, '(a,i0,a)') name//': block ', touched, &
               ' is fully deformable (FDEF) and cannot be cut; nothing was changed'
            call set_error(error, trim(text))
            return
         end if
         if (allocated(guard%bc_corner)) then
            call block_touched(guard%saved, geo, guard%npend0, touched, guard%bc_corner)
            if (touched > 0) then
               geo = guard%saved
               write (text, '(a,i0,a,i0,a)') name//': block ', touched, &
                  ' carries conditions of an earlier BOUNDARY command (corner ', &
                  guard%bc_corner(touched), '); the cut replaces its corners and the ' &
                  //'conditions would be lost: give '//name//' before BOUNDARY; nothing was changed'
               call set_error(error, trim(text))
               return
            end if
         end if
      end if
      if (geo%jplot%on .and. previewed) return
      call cut_summary(name, geo, guard%nlive0, guard%stats0, guard%npend0, guard%nstraddle, out, &
                       guard%straddlers, guard%fit)
      ! the manual's JPLOT previews only JREGION/JSET/CRACK joints
      if (geo%jplot%on) call out%line('Note: JPLOT ' &
         //'records only CRACK and JSET joints; '//name//' has cut the blocks')
   end subroutine cut_finish

   !> BLOCK (see do_block).
   subroutine run_block(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call check_coordinates(parsed, error)
      if (allocated(error)) return
      call do_block(ctx%model, parsed, ctx%out, error)
   end subroutine run_block

   !> ROUND d: rounding length of the corners of blocks made from now on.
   !> EDGE e: the shortest edge a cut may leave.
   subroutine run_length(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      if (parsed%name == 'ROUND') then
         call cut_set_round(ctx%model%geometry, parsed%real_at(1, 1), error)
      else
         call cut_set_edge(ctx%model%geometry, parsed%real_at(1, 1), error)
      end if
   end subroutine run_length

   !> The cutting commands, one shape: check the numbers, guard the FDEF
   !> blocks, cut, summarise (cut_finish); CRACK and JSET write their traces
   !> (SET WRITE).
   !>   SPLIT x1 y1 x2 y2: cut along the whole line through the two points.
   !>   CRACK x1 y1 x2 y2 <JREG>: cut along the segment.
   !>   JSET (see do_jset).
   !>   TUNNEL xc yc r n: cut a circular opening of n sides.
   !>   ARC xc yc xs ys angle n: cut along a circular arc of n segments.
   subroutine run_cut(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      type(cut_guard_t) :: guard
      logical :: traced
      real(wp) :: v(5)
      integer :: j
      associate (model => ctx%model, out => ctx%out)
         if (parsed%name /= 'JSET') then
            call check_coordinates(parsed, error)
            if (allocated(error)) return
            v = 0.0_wp
            do j = 1, min(5, parsed%items(1)%count)
               v(j) = parsed%real_at(1, j)
            end do
         end if
         select case (parsed%name)
         case ('SPLIT', 'CRACK')
            if (parsed%name == 'SPLIT') call require_block(model, 'SPLIT', error)
            if (allocated(error)) return
            ! two coincident points give no direction: SPLIT 0 0 0 0 cut nothing
            ! (or along an arbitrary line) without a word
            if (hypot(v(3) - v(1), v(4) - v(2)) <= max(model%geometry%tol, tiny(1.0_wp))) &
               call set_error(error, parsed%name//': x1,y1 = '//trim(format_real(v(1)))//','// &
                              trim(format_real(v(2)))//' and x2,y2 = '//trim(format_real(v(3)))// &
                              ','//trim(format_real(v(4)))//' are the same point; the '// &
                              trim(merge('line ', 'crack', parsed%name == 'SPLIT'))// &
                              ' needs two distinct points')
         case ('TUNNEL')
            call check_sides('TUNNEL', parsed%int_at(1, 4), error)
            if (.not. allocated(error) .and. v(3) > 0.0_wp .and. parsed%int_at(1, 4) >= 3) &
               call warn_short_sides('TUNNEL', v(3), 360.0_wp, parsed%int_at(1, 4), model%geometry, out)
         case ('ARC')
            call check_sides('ARC', parsed%int_at(1, 6), error)
            if (.not. allocated(error) .and. parsed%int_at(1, 6) >= 1) &
               call warn_short_sides('ARC', hypot(v(3) - v(1), v(4) - v(2)), v(5), &
                                     parsed%int_at(1, 6), model%geometry, out)
         end select
         if (allocated(error)) return
         call cut_begin(model, guard, keep=parsed%name == 'JSET')
         select case (parsed%name)
         case ('SPLIT')
            call cut_split(model%geometry, v(1), v(2), v(3), v(4), error, out)
         case ('CRACK')
            call cut_crack(model%geometry, v(1), v(2), v(3), v(4), parsed%find('JREG') > 0, error, &
                           out, jplot=.true.)
            ! CRACKs closing a loop inside a block (a square drawn side by
            ! side) cut out what it encloses, as a TUNNEL ring does
            if (.not. allocated(error)) &
               call cut_key_pending_loops(model%geometry, guard%npend0, 'CRACK', error, out)
         case ('JSET')
            call do_jset(model, parsed, out, error)
         case ('TUNNEL')
            call joint_tunnel(model%geometry, v(1), v(2), v(3), parsed%int_at(1, 4), error, out, &
                              guard%nstraddle, guard%straddlers, guard%fit)
         case ('ARC')
            call joint_arc(model%geometry, v(1), v(2), v(3), v(4), v(5), parsed%int_at(1, 6), &
                           error, out)
         end select
         traced = parsed%name == 'CRACK' .or. parsed%name == 'JSET'
         call cut_finish(model%geometry, parsed%name, guard, out, error, previewed=traced)
         if (traced) call rjoint_flush(out, error)
      end associate
   end subroutine run_cut

   !> SET WRITE: append the traces the command laid down to the file RJOINT
   !> (x1 y1 x2 y2 block, one line each); a refused command writes nothing.
   subroutine rjoint_flush(out, error)
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(inout) :: error
      integer :: u, ios
      integer(ip) :: i
      if (rjoint_traces%n == 0) return
      if (.not. allocated(error)) then
         open (newunit=u, file=rjoint_file, position='append', status='unknown', &
               action='write', iostat=ios)
         if (ios /= 0) then
            call out%line('*** Warning: SET WRITE: cannot write the file '//rjoint_file)
         else
            do i = 1, rjoint_traces%n
               write (u, '(4es17.8,i8)') rjoint_traces%x1(i), rjoint_traces%y1(i), rjoint_traces%x2(i), &
                  rjoint_traces%y2(i), rjoint_traces%block(i)
            end do
            close (u)
            call out%line('SET WRITE: '//itoa(rjoint_traces%n)//' joint trace(s) written to '// &
                          rjoint_file)
         end if
      end if
      rjoint_traces%n = 0
   end subroutine rjoint_flush

   !> JDELETE: remove the partial cracks.
   subroutine run_jdelete(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      associate (model => ctx%model, out => ctx%out)
         call cannot_fail(error, parsed)
         call cut_remove_partial(model%geometry, out)
      end associate
   end subroutine run_jdelete

   !> JREGION x1 y1 .. x4 y4: the region the next JSET is limited to.
   subroutine run_jregion(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: j
      real(wp) :: x(4), y(4)
      call check_coordinates(parsed, error)
      if (allocated(error)) return
      x = [(parsed%real_at(1, 2*j - 1), j=1, 4)]
      y = [(parsed%real_at(1, 2*j), j=1, 4)]
      call take_clockwise('JREGION', x, y, ctx%out)
      call joint_region(ctx%model%geometry, x, y, error)
   end subroutine run_jregion

   !> The manual asks for corners in clockwise order (BLOCK, JREGION, Section
   !> 4.5); corners given the other way round describe the same polygon, so
   !> they are taken in reverse order with a note rather than refused. A
   !> self-intersecting outline is left as it is for the command's own check.
   subroutine take_clockwise(name, x, y, out)
      character(len=*), intent(in) :: name
      real(wp), intent(inout) :: x(:), y(:)
      type(output_t), intent(in) :: out
      integer :: n
      n = size(x)
      if (n < 3) return
      if (.not. polygon_signed_area(x, y) > 0.0_wp) return
      if (.not. polygon_is_simple(x, y, geometry_tol_rel*max(maxval(x) - minval(x), maxval(y) - minval(y)))) return
      ! the first corner stays first (the 1989 addresses follow the order)
      x(2:n) = x(n:2:-1)
      y(2:n) = y(n:2:-1)
      call out%line('Note: '//name//': the corners were given anticlockwise; taken in reverse '// &
                    '(clockwise) order, as the manual asks (Section 4.5)')
   end subroutine take_clockwise

   !> UPCON: rebuild the contacts and domains now; UPDOM: refresh the
   !> geometry and rebuild the domains now.
   subroutine run_rebuild(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call require_block(ctx%model, parsed%name, error)
      if (allocated(error)) return
      if (parsed%name == 'UPCON') then
         call contact_rebuild(ctx%model%geometry)
      else
         call geometry_refresh(ctx%model%geometry)
      end if
      call domain_rebuild(ctx%model%geometry)
   end subroutine run_rebuild

   !> First guarded block of `before` that a cut changed in `after` (its
   !> corner ring replaced or the block gone); 0 if none. Guarded: the live
   !> FDEF blocks, for which a new partial crack entering the block counts too
   !> (it cuts the block when it joins others), or, with `marks`, the live
   !> blocks b with marks(b) > 0.
   subroutine block_touched(before, after, npend0, b, marks)
      type(geometry_t), intent(in) :: before, after
      integer(ip), intent(in) :: npend0
      integer(ip), intent(out) :: b
      integer(ip), intent(in), optional :: marks(:)
      integer(ip) :: p, np
      real(wp), allocatable :: x(:), y(:), t0(:), t1(:)
      do b = 1, before%blocks%n
         if (.not. before%blocks%live(b)) cycle
         if (present(marks)) then
            if (marks(b) == 0) cycle
         else if (.not. before%blocks%fdef(b)) then
            cycle
         end if
         if (.not. after%blocks%live(b)) return
         if (after%blocks%first_corner(b) /= before%blocks%first_corner(b) .or. &
             after%blocks%ncorner(b) /= before%blocks%ncorner(b)) return
         if (after%pending%n > npend0 .and. .not. present(marks)) then
            call geometry_block_polygon(after, b, x, y)
            do p = npend0 + 1, after%pending%n
               call cut_segment_pieces(x, y, after%pending%x1(p), after%pending%y1(p), &
                                       after%pending%x2(p), after%pending%y2(p), after%tol, &
                                       .true., t0, t1, np)
               if (np > 0) return
            end do
         end if
      end do
      b = 0
   end subroutine block_touched

   subroutine check_sides(command, n, error)
      character(len=*), intent(in) :: command
      integer, intent(in) :: n
      type(error_t), allocatable, intent(out) :: error
      character(len=24) :: text
      if (n > max_polygon_sides) then
         write (text, '(i0)') max_polygon_sides
         call set_error(error, command//': at most '//trim(text)//' segments are allowed '// &
                        '(they follow the circle within 2e-7 of its radius)')
      end if
   end subroutine check_sides

   !> A ring or arc of n sides of radius r over `angle` degrees whose sides are
   !> shorter than EDGE cannot be cut as drawn: a cut that would leave an edge
   !> shorter than EDGE is not made and bends within EDGE are straightened
   !> (geometry_cutting), so the opening comes out coarser, or not separated at
   !> all (a 2 m TUNNEL of 24 sides under the default ROUND 0.5, EDGE 1.0). Say
   !> so before cutting, with the ROUND that would let its sides be cut.
   subroutine warn_short_sides(command, r, angle, n, geo, out)
      character(len=*), intent(in) :: command
      real(wp), intent(in) :: r, angle
      integer, intent(in) :: n
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      real(wp) :: side, turn
      character(len=:), allocatable :: text
      turn = min(abs(angle), 360.0_wp)*pi/180.0_wp
      side = 2.0_wp*r*sin(0.5_wp*turn/real(n, wp))
      if (.not. side < geo%edge_min) return
      text = 'Warning: '//command//': its sides ('//trim(format_real(side))// &
             ') are shorter than EDGE ('//trim(format_real(geo%edge_min))//'; ROUND '// &
             trim(format_real(geo%round))
      if (geo%round == round_default) text = text//', the default'
      text = text//'): a cut leaving an edge shorter than EDGE is not made, so the opening '// &
             'comes out coarser, or is not cut at all; give ROUND below '// &
             trim(format_real(0.5_wp*side))//' (a few percent of the block edges, manual Section 3.3)'
      ! fewer sides are no remedy: the joints the ring crosses cut its sides
      ! into pieces shorter still (a 2 m ring of 12 sides in 1.5 m blocks
      ! under ROUND 0.5 is cut in one block)
      call out%line(text)
   end subroutine warn_short_sides

   !> BLOCK <MAT n> <CONS m> x1 y1 x2 y2 ... | <MAT n> <CONS m> CIRCULAR xc yc r n
   subroutine do_block(model, parsed, out, error)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      type(output_t), intent(in) :: out
      type(error_t), allocatable, intent(out) :: error
      integer :: k, material, cons, loose, circular, n, j
      real(wp), allocatable :: x(:), y(:)
      material = 1
      cons = 1
      loose = 0
      circular = 0
      do k = 1, parsed%nitems
         call parsed%take(k, 'MATERIAL', material)
         call parsed%take(k, 'CONSTITUTIVE', cons)
         if (parsed%items(k)%name == 'CIRCULAR') circular = k
         if (parsed%items(k)%keyword == item_loose) loose = k
      end do
      if (circular > 0 .and. loose > 0) then
         call set_error(error, 'BLOCK: give either corner coordinates or CIRCULAR, not both')
         return
      end if
      if (circular > 0) then
         call check_sides('BLOCK CIRCULAR', parsed%int_at(circular, 4), error)
         if (allocated(error)) return
         call cut_create_circular(model%geometry, parsed%real_at(circular, 1), &
                                  parsed%real_at(circular, 2), parsed%real_at(circular, 3), &
                                  parsed%int_at(circular, 4), material, cons, error)
         return
      end if
      if (loose == 0) then
         call set_error(error, 'BLOCK: expected corner coordinates x1 y1 x2 y2 ... (clockwise)')
         return
      end if
      n = parsed%items(loose)%count/2
      allocate (x(n), y(n))
      do j = 1, n
         x(j) = parsed%real_at(loose, 2*j - 1)
         y(j) = parsed%real_at(loose, 2*j)
      end do
      if (.not. model%geometry%block_created) call take_clockwise('BLOCK', x, y, out)
      call cut_create_block(model%geometry, x, y, material, cons, error)
   end subroutine do_block

   !> JSET a,ad t,td g,gd s,sd <x0 y0> <ad0>
   subroutine do_jset(model, parsed, out, error)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      type(output_t), intent(in) :: out
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: v(11)
      integer :: n, j
      real(wp) :: span, along, across
      n = parsed%items(1)%count
      do j = 1, n
         v(j) = parsed%real_at(1, j)
      end do
      ! the values themselves first, so the count below is never asked of a
      ! negative spacing (it gave a message about a million joints, issue 20)
      if (.not. v(7) - abs(v(8)) > 0.0_wp) then
         call set_error(error, 'JSET: the spacing '//trim(format_real(v(7)))//' with deviation '// &
                        trim(format_real(v(8)))//' is not positive; give a spacing larger than '// &
                        'its deviation')
         return
      end if
      ! Rough count of joint segments: tracks across the model times joints
      ! along a track, with the smallest spacing and trace+gap the deviations allow.
      if (model%geometry%block_created) then
         span = 1.5_wp*model%geometry%extent
         across = span/max(v(7) - abs(v(8)), 1.0e-200_wp)
         along = span/max(v(3) - abs(v(4)) + max(v(5) - abs(v(6)), 0.0_wp), 1.0e-200_wp)
         if (across > max_jset_joints .or. along > max_jset_joints .or. &
             across*max(along, 1.0_wp) > max_jset_joints) then
            call set_error(error, 'JSET: these spacing, trace and gap values would create ' &
                           //'more than a million joint segments in this model')
            return
         end if
         ! the tracks cover the JREGION: joints are drawn (and the random
         ! sequence kept) across all of it, even where there is no block
         if (model%geometry%has_jregion) then
            span = 1.5_wp*max(maxval(model%geometry%jregion_x) - minval(model%geometry%jregion_x), &
                              maxval(model%geometry%jregion_y) - minval(model%geometry%jregion_y))
            across = span/max(v(7) - abs(v(8)), 1.0e-200_wp)
            along = span/max(v(3) - abs(v(4)) + max(v(5) - abs(v(6)), 0.0_wp), 1.0e-200_wp)
            if (across*max(along, 1.0_wp) > max_jset_draws) then
               call set_error(error, 'JSET: the JREGION is '//trim(format_real(span/1.5_wp))// &
                              ' across: these spacing, trace and gap values would draw about ' &
                              //trim(format_real(across*max(along, 1.0_wp)))//' joints in it '// &
                              '(at most 1e8); give a JREGION near the model')
               return
            end if
         end if
      end if
      select case (n)
      case (8)
         call joint_set(model%geometry, v(1:2), v(3:4), v(5:6), v(7:8), error, out)
      case (10)
         call joint_set(model%geometry, v(1:2), v(3:4), v(5:6), v(7:8), error, out, &
                        origin=v(9:10))
      case default
         call joint_set(model%geometry, v(1:2), v(3:4), v(5:6), v(7:8), error, out, &
                        origin=v(9:10), ad0=v(11))
      end select
   end subroutine do_jset

   !> DELETE <range> <AREA armin> | DELETE BLOCK n. A block goes when its
   !> centroid is inside the range (any range form) and, with AREA, its area is
   !> smaller than armin. The area may also be given as a bare fifth number (as
   !> in the manual's application decks).
   subroutine do_delete(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: kb, ka, b, ndeleted, nthrough, nbeyond
      integer(ip) :: bid, bbeyond
      real(wp) :: armin, ext(4), tol, xthrough, ythrough, xbeyond, ybeyond
      logical :: limit
      character(len=80) :: text
      character(len=:), allocatable :: why
      associate (model => ctx%model, out => ctx%out)
         kb = parsed%find('BLOCK')
         if (kb > 0) then
            if (parsed%has_range) then
               call set_error(error, 'DELETE: give either a range or BLOCK n, not both')
               return
            end if
            ! n: the block's 1989 address (manual Section 4.5 DELETE BLOCK)
            call resolve_entity(model, ak_block, int(parsed%int_at(kb, 1), ip), 'DELETE BLOCK', &
                                out, &
                                bid, error)
            if (allocated(error)) return
            call cut_delete_block(model%geometry, bid, error)
            return
         end if
         if (.not. parsed%has_range) then
            call set_error(error, 'DELETE: expected a range (xl xu yl yu) or BLOCK n')
            return
         end if
         limit = .false.
         armin = 0.0_wp
         if (parsed%items(1)%count > 0) then
            limit = .true.
            armin = parsed%real_at(1, 1)
         end if
         ka = parsed%find('AREA')
         if (ka > 0) then
            limit = .true.
            armin = parsed%real_at(ka, 1)
         end if
         ndeleted = 0
         nthrough = 0
         nbeyond = 0
         associate (blocks => model%geometry%blocks)
            ! the model's extent: a deleted block that spans it from side to
            ! side (a joint-bounded strip whose centroid the range holds)
            ! cuts the rest in two, noted below
            ext = 0.0_wp
            if (geometry_live_blocks(model%geometry) > 0) then
               ext(1) = minval(blocks%xmin(1:blocks%n), mask=blocks%live(1:blocks%n))
               ext(2) = maxval(blocks%xmax(1:blocks%n), mask=blocks%live(1:blocks%n))
               ext(3) = minval(blocks%ymin(1:blocks%n), mask=blocks%live(1:blocks%n))
               ext(4) = maxval(blocks%ymax(1:blocks%n), mask=blocks%live(1:blocks%n))
            end if
            tol = 1.0e-6_wp*max(ext(2) - ext(1), ext(4) - ext(3))
            do b = 1, blocks%n
               if (.not. blocks%live(b)) cycle
               if (.not. parsed%range%contains_point(blocks%xc(b), blocks%yc(b))) cycle
               if (limit .and. .not. blocks%area(b) < armin) cycle
               if ((blocks%xmin(b) <= ext(1) + tol .and. blocks%xmax(b) >= ext(2) - tol) .or. &
                   (blocks%ymin(b) <= ext(3) + tol .and. blocks%ymax(b) >= ext(4) - tol)) then
                  nthrough = nthrough + 1
                  if (nthrough == 1) then
                     xthrough = blocks%xc(b)
                     ythrough = blocks%yc(b)
                  end if
               end if
               if (beyond_tunnels(b)) then
                  nbeyond = nbeyond + 1
                  if (nbeyond == 1) then
                     bbeyond = int(b, ip)
                     xbeyond = blocks%xc(b)
                     ybeyond = blocks%yc(b)
                  end if
               end if
               call cut_delete_block(model%geometry, int(b, ip), error)
               if (allocated(error)) return
               ndeleted = ndeleted + 1
            end do
         end associate
         write (text, '(a,i0,a,i0,a)') 'DELETE: ', ndeleted, ' block(s) deleted, ', &
            geometry_live_blocks(model%geometry), ' remain'
         call out%line(trim(text))
         if (nthrough > 0) then
            ! nothing left: "the rest is cut in two" misled (a user's CRACKs
            ! closing a rectangle inside the one block had cut nothing)
            why = 'so the rest is cut in two'
            if (geometry_live_blocks(model%geometry) == 0) why = 'so nothing remains'
            if (model%geometry%pending%n > 0) why = why//' (the '// &
               itoa(model%geometry%pending%n)//' partial CRACK segment(s) given so far cut no '// &
               'block: cracks cut a block only as a chain from its edge to its edge)'
            call out%line('note: DELETE: '//itoa(nthrough)//' deleted block(s) '// &
               'reached across the whole model (the first centred at ('// &
               trim(format_real(xthrough))//', '//trim(format_real(ythrough))//')), '// &
               why//': DELETE takes every block whose centroid is in the range (manual '// &
               'Section 4.5), here whole strips between joints; cut the opening first (TUNNEL, '// &
               'ARC, CRACK) to excavate inside the rock')
         end if
         if (nbeyond > 0) call out%line('note: DELETE: '//itoa(nbeyond)//' deleted block(s) '// &
            'lie outside the TUNNEL ring(s) that reach into the range (the first: block '// &
            itoa(bbeyond)//', centroid ('//trim(format_real(xbeyond))//', '// &
            trim(format_real(ybeyond))//')): DELETE takes every block whose centroid is in '// &
            'the range (manual Section 4.5), rock around the opening too; to excavate the '// &
            'tunnel only, give a range that holds its blocks alone, or DELETE BLOCK n')
         call note_moved_histories(model, out)
      end associate
   contains
      !> True when some TUNNEL ring reaches into the range (its centre or one
      !> of its vertices in it: a heading's range above the springline holds
      !> no centre) and block b lies inside none of those rings: rock outside
      !> the opening the range was most likely meant to excavate. Inside a ring means every corner
      !> inside its polygon or near it (within EDGE, the distance by which
      !> cutting moves a ring's bend onto a corner and the thickness of a
      !> merged sliver, or 1 % of the radius, plus the reach of the ring's
      !> snap onto joints): a
      !> block wrapped round the ring, concave, can have its centroid inside it.
      logical function beyond_tunnels(b) result(beyond)
         integer, intent(in) :: b
         real(wp), allocatable :: px(:), py(:), bx(:), by(:)
         integer(ip) :: k, i
         logical :: inside
         beyond = .false.
         call geometry_block_polygon(ctx%model%geometry, int(b, ip), bx, by)
         associate (tu => ctx%model%geometry%tunnels)
            do k = 1, tu%n
               if (.not. tu%r(k) > 0.0_wp) cycle
               call ring_polygon(tu%xc(k), tu%yc(k), tu%r(k), tu%nside(k), px, py)
               if (.not. parsed%range%contains_point(tu%xc(k), tu%yc(k))) then
                  if (.not. any([(parsed%range%contains_point(px(i), py(i)), &
                                  i = 1, size(px, kind=ip))])) cycle
               end if
               inside = .true.
               do i = 1, size(bx)
                  if (point_in_polygon(px, py, bx(i), by(i))) cycle
                  ! a ring corner near a joint was moved onto it (TUNNEL, by up
                  ! to the snap reach) and the sliver between the moved side
                  ! and the joint (thinner than EDGE) merged into the piece:
                  ! both together (a new user's slope deck: a corner 0.131 m
                  ! out, the corner moved 0.088 and the sliver 0.092 thick,
                  ! EDGE 0.1, reach 0.102)
                  if (polygon_boundary_distance(px, py, bx(i), by(i)) <= &
                      max(ctx%model%geometry%edge_min, 0.01_wp*tu%r(k)) + &
                      ring_snap_reach(ctx%model%geometry, hypot(px(2) - px(1), py(2) - py(1)), &
                                      tu%nside(k))) cycle
                  inside = .false.
                  exit
               end do
               if (inside) then
                  beyond = .false.
                  return
               end if
               beyond = .true.
            end do
         end associate
      end function beyond_tunnels
   end subroutine do_delete

   !> Say which point histories lost their corner, gridpoint or zone to a
   !> DELETE and where each is taken now (engine_history's history_reattach).
   subroutine note_moved_histories(model, out)
      type(model_t), intent(inout) :: model
      type(output_t), intent(inout) :: out
      logical, allocatable :: moved(:)
      integer :: i
      character(len=200) :: line
      if (model%hist%n == 0) return
      allocate (moved(model%hist%n))
      call history_reattach(model%hist, model%geometry, moved)
      do i = 1, model%hist%n
         if (.not. moved(i)) cycle
         if (model%hist%entity(i) > 0) then
            write (line, '(a,i0,5a)') 'note: DELETE: history ', i, ' (', trim(hist_keyword(model%hist%kind(i))), &
               ') lay on a deleted block; now taken at (', &
               trim(format_real(model%hist%px(i)))//', '//trim(format_real(model%hist%py(i))), ')'
         else
            write (line, '(a,i0,3a)') 'note: DELETE: history ', i, ' (', trim(hist_keyword(model%hist%kind(i))), &
               ') lay on a deleted block and has no point left to take; it reads 0'
         end if
         call out%line(trim(line))
      end do
   end subroutine note_moved_histories

   !> Partially-penetrating cracks are removed at the first CYCLE or GENERATE
   !> (manual Sections 4.2 II and 5.2.1).
   subroutine remove_partial_cracks_once(model, out)
      type(model_t), intent(inout) :: model
      type(output_t), intent(in) :: out
      if (model%cycled) return
      model%cycled = .true.
      if (model%geometry%block_created) call cut_remove_partial(model%geometry, out)
   end subroutine remove_partial_cracks_once

   !> SET keywords that belong to the geometry: SEED, EDGE, JMATDF, JCONDF.
   subroutine set_geometry_keyword(model, parsed, k, handled, error)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      logical, intent(out) :: handled
      type(error_t), allocatable, intent(out) :: error
      handled = .true.
      select case (parsed%items(k)%name)
      case ('SEED')
         call geometry_set_seed(model%geometry, int(parsed%int_at(k, 1), i8))
      case ('EDGE')
         call cut_set_edge(model%geometry, parsed%real_at(k, 1), error)
      case ('JMATDF')
         model%geometry%jmat_default = parsed%int_at(k, 1)
      case ('JCONDF')
         if (all([1, 2, 3, 5] /= parsed%int_at(k, 1))) then
            call set_error(error, 'SET JCONDF: unknown joint constitutive number; known: ' &
                           //'1, 2, 3, 5')
            return
         end if
         model%geometry%jcons_default = parsed%int_at(k, 1)
      case default
         handled = .false.
      end select
   end subroutine set_geometry_keyword


   !> A cutting command's summary (at most three lines): blocks before and
   !> after, cuts made, cut ends moved onto corners, bends straightened, cuts
   !> refused by reason; a warning when no block changed, and for TUNNEL
   !> when its ring still crosses blocks. Per-cut notes: SET LOG ON.
   subroutine cut_summary(name, geo, nlive0, stats0, npend0, nstraddle, out, straddlers, fit)
      character(len=*), intent(in) :: name
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: nlive0, stats0(:), npend0, nstraddle
      type(output_t), intent(in) :: out
      !> TUNNEL: the first blocks its ring still crosses (0 past nstraddle)
      integer(ip), intent(in) :: straddlers(:)
      !> TUNNEL: how far its opening departs from the ring drawn
      type(ring_fit_t), intent(in) :: fit
      integer(ip) :: d(ncut_stats), nlive, nref, k
      character(len=:), allocatable :: text
      d = geo%cut_stats - stats0
      nlive = geometry_live_blocks(geo)
      nref = d(cut_refused_short) + d(cut_refused_sliver) + d(cut_refused_shape)
      if (nlive == nlive0 .and. nref == 0) then
         if (geo%pending%n > npend0) then
            call out%line(name//': no block cut yet; '//itoa(geo%pending%n - npend0)// &
                          ' partial crack segment(s) kept until they separate a block')
         else if (name == 'SPLIT') then
            ! SPLIT drops a cut that does not separate a block in two (manual
            ! Section 4): a line ending inside a block is the usual reason
            call out%line('Warning: SPLIT changed no block ('//itoa(nlive)//' blocks): its '// &
                          'line crosses no block from edge to edge (SPLIT drops a cut that '// &
                          'does not separate a block in two; CRACK makes a partial crack), or '// &
                          'lies outside the blocks or along existing edges')
         else if (name == 'TUNNEL' .and. last_ring_radius(geo) == 0.0_wp) then
            ! the manual's way to let later cuts cross the rings again
            call out%line('TUNNEL of zero radius: no block cut; later CRACK, JSET and ARC cuts '// &
                          'cross the rings of earlier TUNNELs again (manual Section 4.5, TUNNEL)')
         else if (name /= 'TUNNEL' .and. last_ring_radius(geo) > 0.0_wp) then
            ! CRACK, JSET and ARC cut only outside the last TUNNEL's ring: a
            ! new user's CRACK across the core of a tunnel (heading and
            ! bench) was told its joints lay outside the blocks
            call out%line('Warning: '//name//' changed no block ('//itoa(nlive)//' blocks); '// &
                          'its joints lie outside the blocks, along existing edges or inside '// &
                          'the ring of the last TUNNEL, which later cuts do not enter (manual '// &
                          'Section 4.5, TUNNEL); to cut inside the ring use SPLIT, or give a '// &
                          'TUNNEL of zero radius outside the model first')
         else
            call out%line('Warning: '//name//' changed no block ('//itoa(nlive)//' blocks); '// &
                          'its joints lie outside the blocks or along existing edges')
         end if
      else
         text = name//': '//itoa(nlive0)//' -> '//itoa(nlive)//' blocks ('//itoa(d(cut_made))// &
                ' cuts made, '//itoa(d(cut_snapped))//' cut ends moved onto corners'
         if (d(cut_bend_moved) > 0) text = text//', '//itoa(d(cut_bend_moved))// &
                                           ' bends straightened'
         if (d(cut_sliver_merged) > 0) text = text//', '//itoa(d(cut_sliver_merged))// &
                                              ' slivers merged into their neighbours'
         call out%line(text//')')
      end if
      if (nref > 0) call out%line('Warning: '//name//': '//itoa(nref)//' cut(s) refused: '// &
                                  itoa(d(cut_refused_short))// &
                                  ' would leave an edge shorter than EDGE, '// &
                                  itoa(d(cut_refused_sliver))// &
                                  ' a sliver that could not be merged, '// &
                                  itoa(d(cut_refused_shape))// &
                                  ' a self-touching block (SET LOG ON lists them)')
      if (nstraddle > 0) then
         ! name the blocks and where they are, for PRINT BLOCK and PLOT
         text = 'Warning: TUNNEL: the ring still crosses '//itoa(nstraddle)//' block(s) ('
         do k = 1, min(nstraddle, size(straddlers, kind=ip))
            if (straddlers(k) <= 0) exit
            if (k > 1) text = text//'; '
            text = text//'block '//itoa(straddlers(k))//' centred at ('// &
                   trim(adjustl(fmt_real(geo%blocks%xc(straddlers(k)), 12, 5)))//', '// &
                   trim(adjustl(fmt_real(geo%blocks%yc(straddlers(k)), 12, 5)))//')'
         end do
         if (nstraddle > size(straddlers)) text = text//'; ...'
         call out%line(text//'): the opening is not separated from the rock there')
      end if
      if (name == 'TUNNEL' .and. fit%n > 0) call warn_ring_fit(geo, fit, out)
   end subroutine cut_summary

   !> TUNNEL's warning when blocks hold more rock on the wrong side of the
   !> ring drawn than a snapped corner moves (ring_fit): DELETE ANN of the
   !> ring would leave that rock in the opening or take it from the wall.
   !> A ROUND whose 2 ROUND exceeds the ring's own snap reach gets the
   !> manual's advice (UDEC manual (ICG1.5), Section 4, ROUND: about one
   !> percent of the typical block edge).
   subroutine warn_ring_fit(geo, fit, out)
      type(geometry_t), intent(in) :: geo
      type(ring_fit_t), intent(in) :: fit
      type(output_t), intent(in) :: out
      character(len=:), allocatable :: text
      integer(ip) :: k, b
      text = 'Warning: TUNNEL: the opening departs from the ring drawn by '// &
             sig3(fit%total)//' m2 in all ('//sig3(100.0_wp*fit%total/fit%ring_area)// &
             ' % of its '//sig3(fit%ring_area)//' m2); '//itoa(fit%n)// &
             ' block(s) hold more than '//sig3(fit%allow)//' m2 on the wrong side ('
      do k = 1, min(fit%n, size(fit%block, kind=ip))
         b = fit%block(k)
         if (k > 1) text = text//'; '
         text = text//'block '//itoa(b)//' centred at ('// &
                trim(adjustl(fmt_real(geo%blocks%xc(b), 12, 5)))//', '// &
                trim(adjustl(fmt_real(geo%blocks%yc(b), 12, 5)))//') '// &
                trim(merge('takes ', 'leaves', fit%taken(k)))//' '//sig3(fit%wrong(k))//' m2 '// &
                trim(merge('outside the ring', 'inside it       ', fit%taken(k)))
      end do
      if (fit%n > size(fit%block)) text = text//'; ...'
      text = trim(text)//' at DELETE ANN of the ring)'
      if (fit%coarse) then
         text = text//': ROUND '//format_real(geo%round)//' (EDGE '// &
                format_real(geo%edge_min)//') is large against the ring''s side '// &
                sig3(fit%side)//' m: a piece of a side shorter than EDGE is not cut, and a '// &
                'corner within 2 ROUND of a joint is moved onto it; the manual recommends a '// &
                'ROUND of about 1 % of the typical block edge (Section 4, ROUND)'
      else
         text = text//': the ring''s cuts were refused or moved there (SET LOG ON lists '// &
                'refused cuts; PLOT BLOCK shows the opening)'
      end if
      call out%line(text)
   contains
      !> v to three significant digits
      function sig3(v) result(t)
         real(wp), intent(in) :: v
         character(len=:), allocatable :: t
         real(wp) :: scale
         if (.not. v > 0.0_wp) then
            t = '0'
            return
         end if
         scale = 10.0_wp**(2 - floor(log10(v)))
         t = format_real(anint(v*scale)/scale)
      end function sig3
   end subroutine warn_ring_fit

   !> Radius of the last TUNNEL's ring, which later cuts do not enter (-1
   !> without a TUNNEL).
   real(wp) function last_ring_radius(geo) result(r)
      type(geometry_t), intent(in) :: geo
      r = -1.0_wp
      if (geo%tunnels%n > 0) r = geo%tunnels%r(geo%tunnels%n)
   end function last_ring_radius



   !> SET SEED, EDGE, JMATDF, JCONDF.
   subroutine set_geometry(ctx, parsed, k, apply, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      logical, intent(in) :: apply
      type(error_t), allocatable, intent(out) :: error
      logical :: handled
      if (.not. apply) return
      call set_geometry_keyword(ctx%model, parsed, k, handled, error)
   end subroutine set_geometry


   !> For each block, the first live corner (in the boundary list's order) that
   !> is a boundary point with a condition (a code other than free, a force, an
   !> increment, a multiplier, a history or a traction), else 0: one pass over
   !> the boundary list.
   function boundary_condition_corners(model) result(corner)
      type(model_t), intent(in) :: model
      integer(ip), allocatable :: corner(:)
      integer(ip) :: k, c, b
      allocate (corner(model%geometry%blocks%n))
      corner = 0
      associate (bnd => model%bound, co => model%geometry%corners)
         do k = 1, bnd%n
            c = bnd%corner(k)
            if (.not. co%live(c)) cycle
            b = co%block(c)
            if (corner(b) /= 0) cycle
            if (bnd%ix(k) /= bc_free .or. bnd%iy(k) /= bc_free .or. bnd%fx(k) /= 0.0_wp .or. &
                bnd%fy(k) /= 0.0_wp .or. bnd%dfx(k) /= 0.0_wp .or. bnd%dfy(k) /= 0.0_wp .or. &
                bnd%xmul(k) /= 1.0_wp .or. bnd%ymul(k) /= 1.0_wp .or. bnd%hx(k) /= bh_constant .or. &
                bnd%hy(k) /= bh_constant .or. boundary_has_traction(bnd, k)) corner(b) = c
         end do
      end associate
   end function boundary_condition_corners

end module commands_geometry
