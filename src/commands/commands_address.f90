!> Commands that name entities by their 1989 address (UDEC manual (ICG1.5,
!> 1989), Section 6.1, and Section 4.5: HISTORY ADDRESS / SDIS n ..., RSET,
!> ISET, DUMP, BOUNDARY CORNER, PFIX DOMAIN, PFREE, DELETE BLOCK). The
!> addresses are bookkeeping (model_address); a number that is no entity's
!> address but is one of our ids (decks written for this program before the
!> addresses existed) is taken as the id, with a note.
module commands_address
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: output_t, itoa
   use model_state, only: model_t
   use model_address, only: address_sync, address_or_id, address_locate, address_field, &
                            address_set_field, address_kind_name, address_describe, &
                            record_length, nak, ak_block, ak_corner, ak_contact, ak_domain, &
                            address_nearest, address_keeps, ak_gridpoint, ak_zone
   use model_address_compat, only: compat_lookup
   use commands_parser, only: parsed_t
   use commands_context, only: context_t
   use contact_refresh, only: geometry_refresh
   implicit none
   private
   public :: resolve_entity, run_set_word, run_dump, resolve_field, addresses_current

contains

   !> Bring the set-up's contacts and domains up to date (the 1989 program
   !> made them as it cut) and give every entity its record.
   subroutine addresses_current(model)
      type(model_t), intent(inout) :: model
      if (.not. model%geometry%block_created) return
      if (.not. model%geometry%contacts_valid .or. .not. model%geometry%domains_valid) &
         call geometry_refresh(model%geometry)
      call address_sync(model%geometry)
   end subroutine addresses_current

   !> The entity of `kind` named by `n` in command `cmd` (see module header).
   !> `id` 0 with `error` set when there is none.
   !> The printed addresses of the manual's decks in the compatibility table
   !> (model_address_compat: Appendix B Problem D's 3445 and 4358, G's 697)
   !> are resolved by it first, in the printed model only, with a note.
   !> `nearest` (HISTORY, which only records): an address that names no
   !> entity of `kind` here (a 1989 address this program does not reproduce
   !> for the model and the table does not hold) is not refused:
   !> the history takes the entity of `kind` whose record starts nearest to
   !> it, and a warning names the address, what its word is here and the
   !> entity taken. Commands that change the model (BOUNDARY CORNER, PFIX,
   !> DELETE BLOCK, RSET) refuse such an address.
   subroutine resolve_entity(model, kind, n, cmd, out, id, error, nearest)
      type(model_t), intent(inout) :: model
      integer, intent(in) :: kind
      integer(ip), intent(in) :: n
      character(len=*), intent(in) :: cmd
      type(output_t), intent(in) :: out
      integer(ip), intent(out) :: id
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: nearest
      character(len=:), allocatable :: how
      character(len=300) :: text
      logical :: near
      near = .false.
      if (present(nearest)) near = nearest
      call addresses_current(model)
      call address_or_id(model%geometry, kind, n, id, how)
      if (how /= 'address') then
         if (compat_taken(model, kind, n, cmd, out, id)) return
      end if
      if (id == 0 .and. near) id = address_nearest(model%geometry, kind, n)
      if (id > 0 .and. how == '') then
         write (text, '(a,a,1x,i0,a,a,a,i0,a)') 'Warning: ', cmd, n, ': no ', &
            address_kind_name(kind), ' has address ', n, &
            ' here (the 1989 numbering of this model is not reproduced;'
         call out%line(trim(text)//' '//word_here(model, n)//'); recording the '// &
                       address_kind_name(kind)//' whose address is nearest: '// &
                       address_describe(model, kind, id))
         return
      end if
      if (id == 0) then
         write (text, '(a,1x,i0,a,a,a,i0,a,a,a)') cmd, n, ': no ', address_kind_name(kind), &
            ' has address ', n, ' (PRINT ', plural(kind), ' lists them in column ADDRESS)'
         call set_error(error, trim(text))
         return
      end if
      if (how == 'id') then
         write (text, '(a,a,1x,i0,a,a,a)') 'note: ', cmd, n, ': no ', address_kind_name(kind), &
            ' has this address; taken as the '
         call out%line(trim(text)//' '//address_describe(model, kind, id))
      else if (id /= n .and. is_live_id(n)) then
         ! n is an address and also another entity's id (the COR column of
         ! PRINT BOUNDARY STATE, PRINT CONTACT's first column): say which is taken
         write (text, '(a,a,1x,i0,a)') 'note: ', cmd, n, ': taken as an address, the'
         call out%line(trim(text)//' '//address_describe(model, kind, id)//'; '// &
                       trim(address_kind_name(kind))//' id '//itoa(n)// &
                       ' is another one')
      end if
   contains
      logical function is_live_id(m)
         integer(ip), intent(in) :: m
         is_live_id = .false.
         if (m < 1) return
         select case (kind)
         case (ak_block)
            if (m <= model%geometry%blocks%n) is_live_id = model%geometry%blocks%live(m)
         case (ak_corner)
            if (m <= model%geometry%corners%n) is_live_id = model%geometry%corners%live(m)
         case (ak_contact)
            if (m <= model%geometry%contacts%n) is_live_id = model%geometry%contacts%live(m)
         case (ak_domain)
            if (m <= model%geometry%domains%n) is_live_id = model%geometry%domains%live(m)
         end select
      end function is_live_id
      function plural(k) result(w)
         integer, intent(in) :: k
         character(len=:), allocatable :: w
         select case (k)
         case (ak_block); w = 'BLOCK'
         case (ak_corner); w = 'CORNERS'
         case (ak_contact); w = 'CONTACT'
         case (ak_domain); w = 'DOMAIN'
         case default; w = 'GRIDPOINT / ZONE'
         end select
      end function plural
   end subroutine resolve_entity

   !> Address `ia` with offset `ioff` (RSET, ISET, HISTORY ADDRESS): the
   !> record holding word ia + ioff, as the 1989 program did (IA(ia+ioff)),
   !> and the field of that word. Errors name the address and offset.
   !> `out` given (HISTORY ADDRESS, which only records): when word ia + ioff
   !> is in no record or is a word this program does not keep (a 1989 address
   !> not reproduced for this model and not in the compatibility table), the
   !> history takes offset ioff of the entity whose record starts nearest to
   !> ia among the kinds that keep offset ioff, with a warning naming both
   !> (resolve_entity's `nearest`).
   recursive subroutine resolve_field(model, cmd, ia, ioff, kind, id, off, name, error, out)
      type(model_t), intent(inout) :: model
      character(len=*), intent(in) :: cmd
      integer(ip), intent(in) :: ia, ioff
      integer, intent(out) :: kind
      integer(ip), intent(out) :: id, off
      character(len=:), allocatable, intent(out) :: name
      type(error_t), allocatable, intent(out) :: error
      type(output_t), intent(in), optional :: out
      character(len=300) :: text
      integer(ip) :: id0, off0
      integer :: k0
      real(wp) :: v
      logical :: found
      call addresses_current(model)
      if (compat_taken(model, 0, ia, cmd, out, id, kind)) then
         off = ioff
         call address_field(model%geometry, kind, id, off, name, v, found, model%fluid)
         if (found) return
         write (text, '(a,1x,i0,1x,i0,a,i0,a,a,a)') cmd, ia, ioff, ': offset ', ioff, &
            ' of that ', address_kind_name(kind), ' is not a variable this program keeps'
         call set_error(error, trim(text))
         return
      end if
      if (present(out)) then
         call address_locate(model%geometry, ia, k0, id0, off0)
         if (k0 > 0 .and. off0 == 0) then
            call resolve_field(model, cmd, ia, ioff, kind, id, off, name, error)
            if (.not. allocated(error)) return
            deallocate (error)
            write (text, '(a,i0,a,a,a,i0,a)') 'offset ', ioff, ' of the ', address_kind_name(k0), &
               ' record at ', ia, ' is not a variable this program keeps'
         else
            text = 'no record starts at address '//itoa(ia)//' here: '// &
                   word_here(model, ia)
         end if
         call nearest_field(trim(text))
         return
      end if
      name = ''
      ! an entity starting at ia: the offset names its field even past the
      ! record length printed in Section 6.1 (KGUY = 12 with NVGP = 12)
      call address_locate(model%geometry, ia, k0, id0, off0)
      if (k0 > 0 .and. off0 == 0) then
         kind = k0
         id = id0
         off = ioff
      else
         call address_locate(model%geometry, ia + ioff, kind, id, off)
      end if
      if (kind == 0) then
         write (text, '(a,1x,i0,1x,i0,a,i0,a)') cmd, ia, ioff, ': address ', ia + ioff, &
            ' is in no record of a block, corner, contact, domain, gridpoint or zone ' // &
            '(PRINT BLOCK / CORNERS / CONTACT / DOMAIN / GRIDPOINT / ZONE STATE list the addresses)'
         call set_error(error, trim(text))
         return
      end if
      call address_field(model%geometry, kind, id, off, name, v, found, model%fluid)
      if (.not. found) then
         write (text, '(a,1x,i0,1x,i0,a,i0,a,a,a,i0,a,i0,a)') cmd, ia, ioff, ': offset ', off, &
            ' of the ', address_kind_name(kind), ' record at address ', ia + ioff - off, &
            ' (length ', record_length(kind), ') is not a variable this program keeps ' // &
            '(Section 6.1 offsets; a pointer of the linked lists or an unused word)'
         call set_error(error, trim(text))
      end if
   contains
      !> Offset ioff of the nearest record (by start address) of a kind that keeps it.
      subroutine nearest_field(reason)
         character(len=*), intent(in) :: reason
         integer :: k
         integer(ip) :: i, dbest, a
         kind = 0
         id = 0
         dbest = huge(1_ip)
         do k = 1, nak
            if (.not. address_keeps(k, ioff)) cycle
            i = address_nearest(model%geometry, k, ia)
            if (i == 0) cycle
            a = entity_address(k, i)
            if (abs(a - ia) < dbest) then
               dbest = abs(a - ia)
               kind = k
               id = i
            end if
         end do
         if (kind == 0) then
            write (text, '(a,1x,i0,1x,i0,a)') cmd, ia, ioff, ': '
            call set_error(error, trim(text)//' '//reason// &
                           '; no record of a kind that keeps offset '// &
                           itoa(ioff)//' exists')
            return
         end if
         off = ioff
         call address_field(model%geometry, kind, id, off, name, v, found, model%fluid)
         write (text, '(a,a,1x,i0,1x,i0,a)') 'Warning: ', cmd, ia, ioff, ': '
         call out%line(trim(text)//' '//reason//' (the 1989 numbering of this model is not '// &
                       'reproduced); recording '//name//' (offset '//itoa(ioff)// &
                       ') of the record nearest to '//itoa(ia)// &
                       ' among the kinds that keep that offset: '// &
                       address_describe(model, kind, id))
      end subroutine nearest_field
      integer(ip) function entity_address(k, i) result(a)
         integer, intent(in) :: k
         integer(ip), intent(in) :: i
         select case (k)
         case (ak_block); a = model%geometry%blocks%addr(i)
         case (ak_corner); a = model%geometry%corners%addr(i)
         case (ak_contact); a = model%geometry%contacts%addr(i)
         case (ak_domain); a = model%geometry%domains%addr(i)
         case (ak_gridpoint); a = model%geometry%gridpoints%addr(i)
         case default; a = model%geometry%zones%addr(i)
         end select
      end function entity_address
   end subroutine resolve_field

   !> Printed address `a` of the manual's Appendix B decks that names no
   !> entity of its kind here, resolved by the compatibility table
   !> (model_address_compat): .true. with `id` (and `kind_out`) and a note
   !> naming the address, the manual's words for the entity and the entity
   !> taken. `kind` 0: any kind the table gives (HISTORY ADDRESS, RSET).
   !> `out` absent: no note (the caller reports).
   logical function compat_taken(model, kind, a, cmd, out, id, kind_out) result(taken)
      type(model_t), intent(inout) :: model
      integer, intent(in) :: kind
      integer(ip), intent(in) :: a
      character(len=*), intent(in) :: cmd
      type(output_t), intent(in), optional :: out
      integer(ip), intent(inout) :: id
      integer, intent(out), optional :: kind_out
      integer :: k
      integer(ip) :: i
      character(len=:), allocatable :: source
      call compat_lookup(model%geometry, a, kind, k, i, source)
      taken = k > 0
      if (present(kind_out)) kind_out = k
      if (.not. taken) return
      id = i
      if (present(out)) then
         call out%line('note: '//cmd//' '//itoa(a)//': 1989 address of the '// &
                       address_kind_name(k)//' of '//source//', not reproduced by this '// &
                       'layout; taken by the compatibility table of the manual''s decks: '// &
                       address_describe(model, k, i))
      end if
   end function compat_taken

   !> RSET v ia ioff / ISET ival ia ioff: the value at address ia, offset
   !> ioff (ISET's value is an integer by its grammar).
   subroutine run_set_word(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: v
      integer :: kind
      integer(ip) :: ia, ioff, id, off
      character(len=:), allocatable :: name, msg
      character(len=300) :: text
      character(len=:), allocatable :: cmd
      cmd = parsed%name
      v = parsed%real_at(1, 1)
      ia = int(parsed%int_at(1, 2), ip)
      ioff = int(parsed%int_at(1, 3), ip)
      call resolve_field(ctx%model, cmd, ia, ioff, kind, id, off, name, error)
      if (allocated(error)) return
      call address_set_field(ctx%model, kind, id, off, v, msg)
      if (len(msg) > 0) then
         write (text, '(a,1x,i0,1x,i0,a,a,a,i0,a,a)') cmd, ia, ioff, ': ', name, ' (offset ', off, &
            ') of the ', address_kind_name(kind)
         call set_error(error, trim(text)//' '//msg)
         return
      end if
      write (text, '(a,a,a,i0,a,g0.6,a)') cmd//': ', name, ' (offset ', off, ') := ', v, ' in '
      call ctx%out%line(trim(text)//' '//address_describe(ctx%model, kind, id))
   end subroutine run_set_word

   !> DUMP n m: the words of the records between addresses n and m, by name;
   !> then MFREE and the number of junk records (Section 4.5 DUMP).
   subroutine run_dump(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: a1, a2, a, id, off
      integer :: kind
      character(len=:), allocatable :: name
      real(wp) :: v
      logical :: found
      character(len=200) :: text
      a1 = int(parsed%int_at(1, 1), ip)
      a2 = int(parsed%int_at(1, 2), ip)
      if (a1 < 1 .or. a2 < a1) then
         write (text, '(a,i0,1x,i0,a)') 'DUMP ', a1, a2, ': expected addresses 1 <= n <= m'
         call set_error(error, trim(text))
         return
      end if
      call addresses_current(ctx%model)
      if (a2 - a1 > 100000_ip) a2 = a1 + 100000_ip
      do a = a1, a2
         call address_locate(ctx%model%geometry, a, kind, id, off)
         if (kind == 0) cycle
         if (off == 0) call ctx%out%line(address_describe(ctx%model, kind, id))
         call address_field(ctx%model%geometry, kind, id, off, name, v, found, ctx%model%fluid)
         if (.not. found) cycle
         write (text, '(i10,a,i3,1x,a8,1x,g0.8)') a, '  +', off, name, v
         call ctx%out%line(trim(text))
      end do
      write (text, '(a,i0,a,i0)') 'MFREE ', ctx%model%geometry%ia%mfree, '   JUNK records ', &
         ctx%model%geometry%ia%njunk
      call ctx%out%line(trim(text))
   end subroutine run_dump

   !> What word `a` is in this program's layout: "word a is offset o of the
   !> <kind> record at r" or "word a is in no record (MFREE m)".
   function word_here(model, a) result(text)
      type(model_t), intent(in) :: model
      integer(ip), intent(in) :: a
      character(len=:), allocatable :: text
      character(len=200) :: buf
      integer :: kind
      integer(ip) :: id, off
      call address_locate(model%geometry, a, kind, id, off)
      if (kind == 0) then
         write (buf, '(a,i0,a,i0,a)') 'word ', a, ' is in no record here (MFREE ', &
            model%geometry%ia%mfree, ')'
      else
         write (buf, '(a,i0,a,i0,a,a,a,i0)') 'word ', a, ' is offset ', off, ' of the ', &
            address_kind_name(kind), ' record at ', a - off
      end if
      text = trim(buf)
   end function word_here

end module commands_address
