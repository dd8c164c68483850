!> Zone pressure sources during a CYCLE (manual SET ZPRESS x y rad pz; the
!> sources live in `boundary_t%zp`, model_boundary). Reading of the manual:
!> docs/zones.md ("Zone pressure").
!>
!>   zones_pressure_step  once per step k = 1..ncycles, right after the zone
!>                        stress pass: every listed zone of source i carries
!>                        an extra isotropic pressure p = pz(i) h_i(t)
!>                        (compression positive), i.e. its effective stress
!>                        for the nodal forces is sigma - p I. For a constant-
!>                        strain triangle with 2A-scaled shape-function
!>                        gradients b_k = (y_{k+1} - y_{k+2}, x_{k+2} - x_{k+1})
!>                        the stress pass adds -(sigma . b_k) / 2 to gridpoint
!>                        k (zones_stress_pass), so the pressure adds
!>                        +p/2 b_k: it pushes the vertices away from the zone.
!>                        The gradients are taken at the current positions.
!>                        No source: returns at once.
!>   zpress_cycle_end     after the last step: the source histories and the
!>                        history for new sources go back to CONSTANT (a
!>                        history is in effect for one CYCLE, as for BOUNDARY
!>                        increments); called by boundary_cycle_end. The
!>                        engine calls that (and boundary_cycle_start, which
!>                        sets the SINE / COSINE start time) only when there
!>                        are boundary points; a history other than CONSTANT
!>                        comes from a BOUNDARY command, which builds them.
!>
!> h_i(t) is model_boundary's boundary_history_value for the source's history
!> (the same function the BOUNDARY kernels use; CONSTANT is 1). Dead zones and
!> zones of dead blocks are skipped. The zone stresses themselves are not
!> changed: PRINT ZONE STRESS shows the stress of the solid (sigma), the
!> pressure is the extra load.
module zones_pressure
   use core_kinds, only: wp, ip, i8
   use core_motion, only: stage_args_t
   use model_geometry, only: geometry_t
   use model_boundary, only: boundary_t, zpress_t, boundary_history_value, bh_constant
   implicit none
   private
   public :: zones_pressure_step, zpress_cycle_end

contains

   !> Step sa%k (1..sa%ncycles) at problem time sa%time (end of the step, as
   !> boundary_step): nodal forces of the source pressures into
   !> geo%gridpoints%fx / fy.
   subroutine zones_pressure_step(bnd, geo, sa)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(inout) :: geo
      type(stage_args_t), intent(in) :: sa
      integer(ip) :: e, s, last, z, g1, g2, g3
      real(wp) :: hp, h, x1, y1, x2, y2, x3, y3
      if (bnd%zp%n == 0) return
      last = 0
      hp = 0.0_wp
      associate (zp => bnd%zp, zn => geo%zones, gp => geo%gridpoints, bl => geo%blocks)
         do e = 1, zp%nz
            s = zp%src(e)
            if (s /= last) then
               last = s
               h = 1.0_wp
               if (zp%h(s) /= bh_constant) h = boundary_history_value(bnd, zp%h(s), zp%freq(s), &
                                                                      zp%tload(s), sa%time, sa%k, &
                                                                      sa%ncycles)
               hp = 0.5_wp*zp%pz(s)*h
            end if
            if (hp == 0.0_wp) cycle
            z = zp%zone(e)
            if (.not. zn%live(z)) cycle
            if (.not. bl%live(zn%block(z))) cycle
            g1 = zn%g1(z); g2 = zn%g2(z); g3 = zn%g3(z)
            x1 = gp%x(g1); y1 = gp%y(g1)
            x2 = gp%x(g2); y2 = gp%y(g2)
            x3 = gp%x(g3); y3 = gp%y(g3)
            ! +p/2 b_k, b_k = 2A grad N_k (zones_stress_pass with sxx = syy = -p)
            gp%fx(g1) = gp%fx(g1) + hp*(y2 - y3)
            gp%fy(g1) = gp%fy(g1) + hp*(x3 - x2)
            gp%fx(g2) = gp%fx(g2) + hp*(y3 - y1)
            gp%fy(g2) = gp%fy(g2) + hp*(x1 - x3)
            gp%fx(g3) = gp%fx(g3) + hp*(y1 - y2)
            gp%fy(g3) = gp%fy(g3) + hp*(x2 - x1)
         end do
      end associate
   end subroutine zones_pressure_step

   !> After the last step of a CYCLE: histories back to CONSTANT.
   subroutine zpress_cycle_end(zp)
      type(zpress_t), intent(inout) :: zp
      zp%h_next = bh_constant
      zp%freq_next = 0.0_wp
      zp%tload_next = 0.0_wp
      if (zp%n == 0) return
      zp%h(1:zp%n) = bh_constant
      zp%freq(1:zp%n) = 0.0_wp
      zp%tload(1:zp%n) = 0.0_wp
   end subroutine zpress_cycle_end

end module zones_pressure
