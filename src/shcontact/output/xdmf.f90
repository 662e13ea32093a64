!> The XDMF sidecar of a result file (issue 15): `OUT.xmf` next to `OUT.h5`, a small XML file
!> that describes the element fields stored in the HDF5 file as meshes, so that ParaView (or any
!> XDMF reader) opens the pressure, tractions, slip and stick/slip state directly.
!>
!> Layout: one temporal collection over the cases that have fields (the "time" is the case
!> number, so ParaView's time slider steps through a sweep), each case a spatial collection of
!> its patches, each patch a structured 2-D mesh (2DSMesh) whose nodes are the element centres
!> of the strip grid (`xy`, the coordinates interleaved: ParaView's XDMF 3 reader crashes on the
!> X_Y geometry of two separate arrays), with the fields as node values. Datasets are referenced by
!> path, with the shapes and number types read from the HDF5 file itself, so the sidecar always
!> matches the file it is written for. It is written under a temporary name and renamed when
!> complete; a file without fields gets no sidecar (and loses a stale one, when that is a regular
!> file written by shcontact: [[is_xdmf_sidecar]]; anything else is left alone).
module shcontact_output_xdmf
   use shcontact_core_error, only: error_type, fatal_error, stat_io
   use shcontact_core_strings, only: str_int, substituted
   use shcontact_core_files, only: rename_file, delete_file, process_id, path_kind
   use shcontact_output_hdf5, only: h5_file_type, h5_open, h5_close, h5_exists, h5_dataset_info
   use shcontact_core_text, only: string_type
   implicit none
   private

   public :: write_xdmf_sidecar, xdmf_name, is_xdmf_sidecar, sidecar_target

   !> The element fields a patch grid can carry, in the order they are listed.
   character(len=*), parameter :: field_names(5) = [character(len=5) :: 'pn', 'px', 'py', &
      'slip', 'state']

contains

   !> The sidecar's name: the HDF5 file's name with `.xmf` for its extension.
   pure function xdmf_name(h5_name) result(name)
      !> Name of the HDF5 file.
      character(len=*), intent(in) :: h5_name
      character(len=:), allocatable :: name
      integer :: dot, slash
      dot = index(h5_name, '.', back=.true.)
      slash = index(h5_name, '/', back=.true.)
      if (dot > slash + 1) then
         name = h5_name(1:dot - 1)//'.xmf'
      else
         name = h5_name//'.xmf'
      end if
   end function xdmf_name

   !> Write the sidecar of the result file `h5_name` for the cases `cases` stored in the groups
   !> `groups` (`cases/000042`); only those with element fields appear.
   subroutine write_xdmf_sidecar(h5_name, cases, groups, error)
      !> Name of the (complete) HDF5 file.
      character(len=*), intent(in) :: h5_name
      !> Case numbers.
      integer, intent(in) :: cases(:)
      !> Their groups in the file.
      type(string_type), intent(in) :: groups(:)
      !> Set when the file cannot be read or the sidecar cannot be written (none is left then).
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type) :: file
      character(len=:), allocatable :: name, temp, ref, msg
      character(len=512) :: iomsg
      integer :: unit, stat, cstat, i, k, n_grids
      logical :: opened

      name = xdmf_name(h5_name)
      temp = name//'.tmp'//str_int(process_id())
      ref = h5_name(index(h5_name, '/', back=.true.) + 1:)
      call h5_open(file, h5_name, error)
      if (allocated(error)) return
      ! status 'new': never overwrite a file of that name.
      open (newunit=unit, file=temp, status='new', action='write', iostat=stat, &
         iomsg=iomsg)
      if (stat /= 0) then
         call h5_close(file)
         call fatal_error(error, 'cannot write the XDMF sidecar "'//temp//'": '// &
            trim(iomsg), stat_io)
         return
      end if
      write (unit, '(a)', iostat=stat) '<?xml version="1.0" ?>', &
         '<!DOCTYPE Xdmf SYSTEM "Xdmf.dtd" []>', &
         '<!-- Element fields of '//xml_escaped(ref, comment=.true.)// &
         ' (shcontact); open this file in ParaView. -->', &
         '<Xdmf Version="3.0">', '  <Domain>', &
         '    <Grid Name="cases" GridType="Collection" CollectionType="Temporal">'
      n_grids = 0
      do i = 1, size(cases)
         if (stat /= 0 .or. allocated(error)) exit
         ! A summary-only file: nothing to look up case by case.
         if (i == 1 .and. .not. h5_exists(file, 'cases')) exit
         if (.not. has_fields(file, groups(i)%text//'/patch_1')) cycle
         write (unit, '(a)', iostat=stat) '      <Grid Name="case_'//str_int(cases(i))// &
            '" GridType="Collection" CollectionType="Spatial">', &
            '        <Time Value="'//str_int(cases(i))//'"/>'
         k = 1
         do while (has_fields(file, groups(i)%text//'/patch_'//str_int(k)))
            call write_patch_grid(unit, file, ref, groups(i)%text//'/patch_'//str_int(k), &
               'case_'//str_int(cases(i))//'_patch_'//str_int(k), stat, error)
            if (stat /= 0 .or. allocated(error)) exit
            n_grids = n_grids + 1
            k = k + 1
         end do
         if (stat == 0) write (unit, '(a)', iostat=stat) '      </Grid>'
      end do
      if (stat == 0) write (unit, '(a)', iostat=stat) '    </Grid>', '  </Domain>', '</Xdmf>'
      call h5_close(file)
      cstat = 0
      inquire (unit=unit, opened=opened)
      if (opened) close (unit, iostat=cstat)
      if (stat == 0) stat = cstat
      if (allocated(error) .or. stat /= 0 .or. n_grids == 0) then
         if (delete_file(temp)) continue
         ! No sidecar, and none left over from an earlier run under this name (only one that
         ! shcontact wrote).
         if (is_xdmf_sidecar(name)) then
            if (delete_file(name)) continue
         end if
         if (stat /= 0 .and. .not. allocated(error)) then
            msg = 'cannot write the XDMF sidecar "'//name//'"'
            call fatal_error(error, msg, stat_io)
         end if
         return
      end if
      call rename_file(temp, name, error)
      if (allocated(error)) then
         if (delete_file(temp)) continue
      end if
   end subroutine write_xdmf_sidecar

   !> True for a regular file (not a link) that is an XDMF sidecar written by shcontact: its
   !> first lines hold the `<Xdmf` element and the comment naming shcontact.
   function is_xdmf_sidecar(name) result(yes)
      !> The file.
      character(len=*), intent(in) :: name
      logical :: yes
      character(len=:), allocatable :: head
      head = file_head(name)
      yes = index(head, '<?xml') == 1 .and. index(head, ' (shcontact); ') > 0 .and. &
         index(head, '<Xdmf ') > 0
   end function is_xdmf_sidecar

   !> The name of the result file (without its folder) that the shcontact sidecar `name`
   !> describes, as its header comment gives it; '' when `name` is no such sidecar.
   function sidecar_target(name) result(described)
      !> The sidecar.
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: described
      character(len=*), parameter :: before = '<!-- Element fields of ', after = ' (shcontact); '
      character(len=:), allocatable :: head
      integer :: i, j
      described = ''
      if (.not. is_xdmf_sidecar(name)) return
      head = file_head(name)
      i = index(head, before)
      j = index(head, after)
      if (i > 0 .and. j > i + len(before)) described = xml_unescaped(head(i + len(before):j - 1))
   end function sidecar_target

   !> The first 2048 bytes of a regular file (the header comment with a name of 255 bytes,
   !> each escaped to at most 5) (fewer when it is shorter; '' when it cannot be
   !> read or is not a regular file).
   function file_head(name) result(head)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: head
      character(len=2048) :: buffer
      integer :: unit, stat, size_
      head = ''
      if (path_kind(name) /= 'file') return
      open (newunit=unit, file=name, status='old', action='read', access='stream', &
         form='unformatted', iostat=stat)
      if (stat /= 0) return
      inquire (unit=unit, size=size_)
      if (size_ > 0) then
         read (unit, iostat=stat) buffer(1:min(size_, len(buffer)))
         if (stat == 0) head = buffer(1:min(size_, len(buffer)))
      end if
      close (unit)
   end function file_head

   !> True when a patch group holds the element grid.
   logical function has_fields(file, patch)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: patch
      has_fields = h5_exists(file, patch//'/tangential/xy')
   end function has_fields

   !> One patch: a 2DSMesh on the element centres, with every field found as node values.
   subroutine write_patch_grid(unit, file, ref, patch, name, stat, error)
      integer, intent(in) :: unit
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: ref, patch, name
      integer, intent(out) :: stat
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: path, mesh_dims
      integer, allocatable :: dims(:)
      integer :: i, type_size
      logical :: is_float

      path = patch//'/tangential'
      call h5_dataset_info(file, path//'/xy', dims, type_size, is_float, error)
      if (allocated(error)) return
      if (size(dims) /= 3) then
         call fatal_error(error, file%name//': '//path//'/xy is not a 3-D dataset', stat_io)
         return
      end if
      ! XDMF lists dimensions slowest first: strips, then elements along a strip.
      mesh_dims = str_int(dims(3))//' '//str_int(dims(2))
      write (unit, '(a)', iostat=stat) '        <Grid Name="'//name//'" GridType="Uniform">', &
         '          <Topology TopologyType="2DSMesh" Dimensions="'//mesh_dims//'"/>', &
         '          <Geometry GeometryType="XY">', &
         '            <DataItem Dimensions="'//mesh_dims//' 2" NumberType="Float" '// &
         'Precision="'//str_int(type_size)//'" Format="HDF">'//xml_escaped(ref)//':/'//path// &
         '/xy</DataItem>'
      if (stat /= 0) return
      write (unit, '(a)', iostat=stat) '          </Geometry>'
      do i = 1, size(field_names)
         if (stat /= 0 .or. allocated(error)) return
         if (.not. h5_exists(file, path//'/'//trim(field_names(i)))) cycle
         write (unit, '(a)', iostat=stat) '          <Attribute Name="'// &
            trim(field_names(i))//'" AttributeType="Scalar" Center="Node">'
         call write_item(unit, file, ref, path//'/'//trim(field_names(i)), mesh_dims, &
            '            ', stat, error)
         if (stat == 0 .and. .not. allocated(error)) write (unit, '(a)', iostat=stat) &
            '          </Attribute>'
      end do
      if (stat == 0 .and. .not. allocated(error)) write (unit, '(a)', iostat=stat) &
         '        </Grid>'
   end subroutine write_patch_grid

   !> A DataItem referring to a dataset, with its number type from the file; the dataset must
   !> have the mesh's shape.
   subroutine write_item(unit, file, ref, path, mesh_dims, indent, stat, error)
      integer, intent(in) :: unit
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: ref, path, mesh_dims, indent
      integer, intent(out) :: stat
      type(error_type), allocatable, intent(out) :: error
      integer, allocatable :: dims(:)
      integer :: type_size
      logical :: is_float
      character(len=:), allocatable :: number_type

      stat = 0
      call h5_dataset_info(file, path, dims, type_size, is_float, error)
      if (allocated(error)) return
      if (size(dims) /= 2) then
         call fatal_error(error, file%name//': '//path//' is not a 2-D field', stat_io)
         return
      end if
      if (str_int(dims(2))//' '//str_int(dims(1)) /= mesh_dims) then
         call fatal_error(error, file%name//': '//path//' does not have the shape of its '// &
            'element grid', stat_io)
         return
      end if
      if (is_float) then
         number_type = 'Float'
      else if (type_size == 1) then
         number_type = 'Char'
      else
         number_type = 'Int'
      end if
      write (unit, '(a)', iostat=stat) indent//'<DataItem Dimensions="'//mesh_dims// &
         '" NumberType="'//number_type//'" Precision="'//str_int(type_size)// &
         '" Format="HDF">'//xml_escaped(ref)//':/'//path//'</DataItem>'
   end subroutine write_item

   !> A file name as XML text: `&`, `<`, `>` as entities; in a comment (`comment`), which may
   !> hold no `--` and not end in `-`, also every `-` as `&#45;` when the name has either
   !> (the sidecar's header comment names its result file; [[xml_unescaped]] reads it back).
   pure function xml_escaped(text, comment) result(escaped)
      character(len=*), intent(in) :: text
      logical, intent(in), optional :: comment
      character(len=:), allocatable :: escaped
      escaped = substituted(substituted(substituted(text, '&', '&amp;'), '<', '&lt;'), '>', '&gt;')
      if (.not. present(comment)) return
      if (.not. comment .or. len(text) == 0) return
      if (index(text, '--') > 0 .or. text(len(text):) == '-') &
         escaped = substituted(escaped, '-', '&#45;')
   end function xml_escaped

   !> The text of [[xml_escaped]] back.
   pure function xml_unescaped(text) result(plain)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: plain
      plain = substituted(substituted(substituted(substituted(text, '&#45;', '-'), '&lt;', '<'), '&gt;', &
         '>'), '&amp;', '&')
   end function xml_unescaped

end module shcontact_output_xdmf
