!> Settings and clock of the explicit mechanical calculation (manual Sections
!> 3.4-3.6, 4.5 CYCLE, DAMP, FRACTION, MSCALE, SET). The per-entity state
!> (velocities, forces, contact forces) lives in the geometry lists; this type
!> holds what is global: time, step, damping, mass scaling and the contact
!> update settings.
module model_mechanics
   use core_kinds, only: wp, ip, i8
   implicit none
   private
   public :: damping_load_changed
   public :: mechanics_t, damping_none, damping_auto, damping_rayleigh, damping_local, &
             damping_static, zone_fraction

   !> damping_local: DAMP LOCAL alpha, an extension (not in the 1989 manual):
   !> every degree of freedom gets the force -alpha |F| sign(v) of its own
   !> unbalanced force F (docs/mechanics.md, "Time step and damping")
   integer, parameter :: damping_none = 0, damping_auto = 1, damping_rayleigh = 2, &
                         damping_local = 3

   type :: mechanics_t
      real(wp) :: time = 0.0_wp          !< problem (mechanical) time
      integer(i8) :: step = 0_i8         !< cycles executed since the model began
      real(wp) :: dt = 0.0_wp            !< time step of the last cycle
      ! FRACTION fb fz fw
      real(wp) :: frac_block = 0.1_wp
      real(wp) :: frac_zone = 1.0_wp
      real(wp) :: frac_fluid = 1.0_wp
      ! DAMP
      integer :: damping = damping_none
      !> a DAMP command set the model's damping (on or off) in this session;
      !> SOLVE switches DAMP AUTO on when none was given (not saved: a restored
      !> model with no damping counts as not given)
      logical :: damping_given = .false.
      real(wp) :: auto_fac = 0.5_wp, auto_mult1 = 0.99_wp, auto_mult2 = 1.05_wp
      real(wp) :: auto_alpha = 0.0_wp    !< current adaptive damping constant [1/s]
      !> DAMP AUTO after a load change on a zoned model (damping_load_changed):
      !> the probe's clock, < 0 while no such load is settling (saved, schema
      !> 18: a restored model damps as the run it continues), the latest estimate
      !> of the driven mode's frequency [rad/s] and the one the clock started
      !> from (engine_cycle damping_probe)
      real(wp) :: probe_time = -1.0_wp
      real(wp) :: probe_w = 0.0_wp, probe_wref = 0.0_wp
      real(wp) :: local_alpha = 0.8_wp   !< DAMP LOCAL alpha (fraction of |F|, 0 < alpha < 1)
      real(wp) :: kinetic_old = -1.0_wp  !< kinetic energy at the previous step (< 0: unknown)
      real(wp) :: rayleigh_fcrit = 0.0_wp, rayleigh_freq = 0.0_wp
      logical :: rayleigh_mass = .true., rayleigh_stiff = .true.
      !> DAMP fcrit freq INTERNAL: Rayleigh damping of the three strain modes
      !> of simply-deformable blocks only (rigid motion keeps its own damping)
      real(wp) :: internal_fcrit = 0.0_wp, internal_freq = 0.0_wp
      logical :: internal_mass = .true., internal_stiff = .true.
      ! MSCALE ON zc bc / OFF
      logical :: mscale = .false.
      real(wp) :: mscale_zone = 0.0_wp, mscale_block = 0.0_wp
      logical :: mscale_part = .false.   !< MSCALE PART tdel: only zones too light for tdel
      real(wp) :: mscale_tdel = 0.0_wp
      ! SET UPCON n, DSCAN n, CSCAN n, OVTOL t, CLEMIN c
      integer(ip) :: nupcon = 1, dscan = 3, cscan = 100
      real(wp) :: ovtol = 0.0_wp         !< 0: one-half the rounding length
      real(wp) :: clemin = 0.0_wp        !< 0: 1/10 of the average contact length
      real(wp) :: clemin_auto = 0.0_wp   !< that default, kept while no contact has a length
      ! contact update bookkeeping
      real(wp) :: motion_since_scan = 0.0_wp   !< largest block travel since the last search
      !> The last search for new contacts (contact_scan) still stands: set by
      !> each search (engine_cycle, search_done), cleared after every command
      !> that could change what a search finds: the blocks' corners and
      !> rings, the contacts, the rounding or the extent (commands_session,
      !> search_kept: all but the ones known to keep it) and before each
      !> mechanical hand-over of a thermal RUN. While it holds and the
      !> travel since is under a quarter of the margin, a CYCLE skips its
      !> opening search. Saved (schema 17): a restart goes on as the run did.
      logical :: search_current = .false.
      !> list lengths (blocks, corners, contacts) and margin at that search
      integer(ip) :: search_sizes(3) = 0
      real(wp) :: search_margin = 0.0_wp
      real(wp) :: unbalanced = 0.0_wp    !< maximum unbalanced force of the last cycle
      logical :: masses_valid = .false.  !< block masses follow the current densities
      !> FXHIS, FYHIS (manual Section 6): value of the x / y boundary history
      !> in the last step (HISTORY XHIS / YHIS); 1 when no history acts
      real(wp) :: fxhis = 1.0_wp, fyhis = 1.0_wp
   end type mechanics_t

contains

   !> The damping meant for static solutions: AUTO (the manual's) or LOCAL
   !> (the extension). The stages that only make sense for a model brought
   !> to rest (the turn hold of a model held by stresses alone) ask this.
   pure logical function damping_static(m)
      type(mechanics_t), intent(in) :: m
      damping_static = m%damping == damping_auto .or. m%damping == damping_local
   end function damping_static

   !> A static load changed (BOUNDARY STRESS / XLOAD / YLOAD, LOAD) on a model
   !> that has stepped: under DAMP AUTO the next CYCLE restarts the adaptive
   !> alpha at its upper bound 1 / dt (engine_cycle clamps the marker to it).
   !> At rest alpha drifts down (to 240 1/s on a block whose critical value is
   !> 4 470 1/s, docs/closed_form.md finding A) and grows 5 % a step (mult2),
   !> so a load given at once met almost no damping and rang to twice its
   !> static change, breaking a joint at 40 % of its tensile strength.
   !> Mass damping alpha gives mode w the ratio alpha / (2 w): at 1 / dt every
   !> mode the step resolves (w dt < 0.5 at FRACTION 0.1) is past critical and
   !> reaches its new rest without overshoot, and the rule (mult1 0.99 while
   !> the damping takes more than fac times the change of kinetic energy)
   !> brings alpha back down as the model settles (docs/mechanics.md).
   !> Not in a model with zones (`zoned`): their gridpoints' step is Gershgorin's
   !> critical one (w dt up to 2), their slow modes are hundreds of steps long,
   !> and at 1 / dt they creep at their terminal speed while the rule cuts alpha
   !> 1 % a step before the load has moved them (docs/robustness.md, round 4a;
   !> the restart also moved verification.closed_forms_salencon from +0.3 % to
   !> +2.3 % of its closed form). A zoned model starts a probe instead: the
   !> cycle sets alpha to twice the frequency of the step's motion (its
   !> Rayleigh quotient, critical for the mode the load drives) until that mode
   !> has settled, and the rule goes on from there (engine_cycle, damping_probe;
   !> the cycle drops the probe where a zone's law is plastic).
   pure subroutine damping_load_changed(m, zoned)
      type(mechanics_t), intent(inout) :: m
      logical, intent(in) :: zoned
      if (m%damping /= damping_auto .or. m%step <= 0) return
      if (zoned) then
         m%probe_time = 0.0_wp
         m%probe_w = 0.0_wp
         m%probe_wref = huge(1.0_wp)
      else
         m%auto_alpha = huge(1.0_wp)
      end if
   end subroutine damping_load_changed

   !> The fraction of the gridpoints' critical step the cycle takes: FRACTION's
   !> fz, under DAMP LOCAL divided by sqrt(1 + alpha). The local force
   !> -alpha |F| sign(v) adds alpha |F| to the restoring force while a point
   !> moves away from rest, so the central-difference step of an oscillator
   !> k / m is stable only for dt sqrt(k / m) < 2 / sqrt(1 + alpha) (1.49 at
   !> alpha 0.8, not 2; at fz = 1 the sliver zones at the tip of a 7 degree
   !> wedge grew to 0.07 m/s in 500 cycles: docs/robustness.md, round 2).
   !> The zones' step is the critical step of Gershgorin's bound and fz = 1
   !> takes all of it; the blocks' fb = 0.1 leaves the margin already.
   pure real(wp) function zone_fraction(m) result(f)
      type(mechanics_t), intent(in) :: m
      f = m%frac_zone
      if (m%damping == damping_local) f = f/sqrt(1.0_wp + max(0.0_wp, m%local_alpha))
   end function zone_fraction

end module model_mechanics
