!> The checkpoint of a sweep: the block files in the work folder OUT.h5.partial/, their list
!> `blocks.txt` and the other names shcontact gives there (shcontact_batch_sweep describes the
!> scheme). Only these names are ever written or removed in the folder.
module shcontact_batch_checkpoint
   use shcontact_core_error, only: error_type, fatal_error, stat_io
   use shcontact_core_textfile, only: text_line_type, read_text_lines
   use shcontact_input_config, only: case_config_type
   use shcontact_output_results, only: run_info_type, write_result_file
   use shcontact_core_files, only: remove_directory, delete_file, file_exists, rename_file
   use shcontact_core_text, only: string_list_type
   use shcontact_case_result, only: case_result_type
   implicit none
   private

   public :: merged_temp_name, key_name, lock_name
   public :: commit_block, read_manifest, write_text_file, read_text_file, clear_checkpoint

   !> Name of the checkpoint list inside the checkpoint directory. It lists the block files by
   !> their names in the directory (block_NNNNNN.h5), so that a run can be resumed from any
   !> working directory; entries of any other form are ignored, never opened or deleted.
   character(len=*), parameter :: manifest_name = 'blocks.txt'
   !> Temporary name of the merged output inside the checkpoint directory (a kill during the
   !> final assembly leaves it there, where the next run removes it).
   character(len=*), parameter :: merged_temp_name = 'merged.h5.tmp'
   !> The configuration of the run that made the checkpoint (shcontact_batch_sweep's
   !> `checkpoint_key`).
   character(len=*), parameter :: key_name = 'configuration.txt'
   !> The lock file of the work folder, held (flock) while a run uses the folder.
   character(len=*), parameter :: lock_name = 'lock'
   !> Suffix of a block file being written.
   character(len=*), parameter :: temp_suffix = '.tmp'

contains

   !> Write a block file and add it to the list.
   subroutine commit_block(dir, blocks, info, config, cases, results, error)
      character(len=*), intent(in) :: dir
      type(string_list_type), intent(inout) :: blocks
      type(run_info_type), intent(in) :: info
      type(case_config_type), intent(in) :: config
      integer, intent(in) :: cases(:)
      type(case_result_type), intent(in) :: results(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: name
      integer :: number
      ! After the last listed block (a resumed list may miss some numbers).
      number = 1
      if (blocks%n > 0) number = block_number(base_name(blocks%items(blocks%n)%text)) + 1
      name = dir//'/'//block_name(number)
      call write_result_file(name, info, config, cases, results, error, &
         temp_name=name//temp_suffix, checkpoint=.true.)
      if (allocated(error)) return
      call blocks%push(name)
      call write_manifest(dir, blocks, error)
   end subroutine commit_block

   !> Rewrite the list of block files (through a temporary file and a rename).
   subroutine write_manifest(dir, blocks, error)
      character(len=*), intent(in) :: dir
      type(string_list_type), intent(in) :: blocks
      type(error_type), allocatable, intent(out) :: error
      integer :: unit, stat, i
      character(len=:), allocatable :: name
      name = dir//'/'//manifest_name
      open (newunit=unit, file=name//temp_suffix, status='replace', action='write', iostat=stat)
      if (stat /= 0) then
         call fatal_error(error, 'cannot write the checkpoint list "'//name//'"', stat_io)
         return
      end if
      do i = 1, blocks%n
         write (unit, '(a)', iostat=stat) base_name(blocks%items(i)%text)
      end do
      close (unit)
      if (stat /= 0) then
         call fatal_error(error, 'cannot write the checkpoint list "'//name//'"', stat_io)
         return
      end if
      call rename_file(name//temp_suffix, name, error)
   end subroutine write_manifest

   !> The block files listed in the checkpoint directory, as paths inside it. Only entries
   !> named like a block file count (an older list's `OUT.h5.partial/block_N.h5` gives
   !> `block_N.h5` in `dir`); anything else in the list is ignored.
   subroutine read_manifest(dir, blocks)
      character(len=*), intent(in) :: dir
      type(string_list_type), intent(out) :: blocks
      type(text_line_type), allocatable :: lines(:)
      type(error_type), allocatable :: error
      character(len=:), allocatable :: name
      integer :: i
      blocks%n = 0
      if (.not. file_exists(dir//'/'//manifest_name)) return
      call read_text_lines(dir//'/'//manifest_name, 'checkpoint list', lines, error)
      if (allocated(error)) return
      do i = 1, size(lines)
         name = base_name(trim(adjustl(lines(i)%text)))
         if (block_number(name) > 0) call blocks%push(dir//'/'//name)
      end do
   end subroutine read_manifest

   !> block_NNNNNN.h5 (six digits or more).
   pure function block_name(number) result(name)
      integer, intent(in) :: number
      character(len=:), allocatable :: name
      character(len=12) :: buf
      write (buf, '(i6.6)') number
      name = 'block_'//trim(buf)//'.h5'
   end function block_name

   !> The number of a block file name, 0 when the name is not one.
   pure integer function block_number(name) result(number)
      character(len=*), intent(in) :: name
      integer :: n, stat
      number = 0
      n = len(name)
      if (n < 15) return
      if (name(1:6) /= 'block_' .or. name(n - 2:n) /= '.h5') return
      if (verify(name(7:n - 3), '0123456789') /= 0 .or. n - 9 > 9) return
      read (name(7:n - 3), *, iostat=stat) number
      if (stat /= 0) number = 0
      if (name /= block_name(number)) number = 0
   end function block_number

   !> The name after the last '/'.
   pure function base_name(path) result(name)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: name
      name = path(index(path, '/', back=.true.) + 1:)
   end function base_name

   !> Write a text file whole (through a temporary name).
   subroutine write_text_file(name, text, error)
      character(len=*), intent(in) :: name, text
      type(error_type), allocatable, intent(out) :: error
      integer :: unit, stat
      open (newunit=unit, file=name//temp_suffix, status='replace', action='write', &
         access='stream', form='unformatted', iostat=stat)
      if (stat == 0) write (unit, iostat=stat) text
      if (stat == 0) close (unit, iostat=stat)
      if (stat /= 0) then
         call fatal_error(error, 'cannot write "'//name//'"', stat_io)
         return
      end if
      call rename_file(name//temp_suffix, name, error)
   end subroutine write_text_file

   !> A text file whole ('' when it cannot be read).
   function read_text_file(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      integer :: unit, stat, n
      text = ''
      open (newunit=unit, file=name, status='old', action='read', access='stream', &
         form='unformatted', iostat=stat)
      if (stat /= 0) return
      inquire (unit=unit, size=n)
      if (n > 0) then
         deallocate (text)
         allocate (character(len=n) :: text)
         read (unit, iostat=stat) text
         if (stat /= 0) text = ''
      end if
      close (unit)
   end function read_text_file

   !> Remove the block files, their temporaries, the list and (unless kept) the directory of a
   !> checkpoint. Only names shcontact gives inside `dir` are removed: block_N.h5 and
   !> block_N.h5.tmp (N = 1, 2, ... while one exists, and every listed N), the list, the
   !> merged temporary. A directory holding anything else is left in place.
   subroutine clear_checkpoint(dir, keep_directory)
      character(len=*), intent(in) :: dir
      logical, intent(in) :: keep_directory
      type(string_list_type) :: blocks
      integer :: i, last
      call read_manifest(dir, blocks)
      last = 0
      do i = 1, blocks%n
         last = max(last, block_number(base_name(blocks%items(i)%text)))
      end do
      i = 1
      do while (i <= last .or. file_exists(dir//'/'//block_name(i)) .or. &
                file_exists(dir//'/'//block_name(i)//temp_suffix))
         if (delete_file(dir//'/'//block_name(i))) continue
         if (delete_file(dir//'/'//block_name(i)//temp_suffix)) continue
         i = i + 1
      end do
      if (delete_file(dir//'/'//merged_temp_name)) continue
      if (delete_file(dir//'/'//key_name)) continue
      if (delete_file(dir//'/'//key_name//temp_suffix)) continue
      if (delete_file(dir//'/'//manifest_name//temp_suffix)) continue
      if (delete_file(dir//'/'//manifest_name)) continue
      if (.not. keep_directory) then
         ! The lock goes last, while still held (the caller closes it).
         if (delete_file(dir//'/'//lock_name)) continue
         if (remove_directory(dir)) continue
      end if
   end subroutine clear_checkpoint

end module shcontact_batch_checkpoint
