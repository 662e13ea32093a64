!> A growable text buffer: appending costs time proportional to the piece, not to the text
!> so far (input with 100 000 values stays linear, issue 24 item 9).
module shcontact_core_buffer
   implicit none
   private

   public :: text_buffer_type

   !> Text built piece by piece; `data(1:n)` holds it.
   type :: text_buffer_type
      !> Storage (capacity = its length).
      character(len=:), allocatable :: data
      !> Characters in use.
      integer :: n = 0
   contains
      !> Append a piece.
      procedure :: add => buffer_add
      !> The text so far.
      procedure :: text => buffer_text
      !> Forget the text (keeps the storage).
      procedure :: clear => buffer_clear
   end type text_buffer_type

contains

   !> Append `piece`, doubling the storage when it is full.
   pure subroutine buffer_add(self, piece)
      !> The buffer.
      class(text_buffer_type), intent(inout) :: self
      !> The text to append.
      character(len=*), intent(in) :: piece
      character(len=:), allocatable :: grown
      if (.not. allocated(self%data)) allocate (character(len=max(256, 2*len(piece))) :: &
         self%data)
      if (self%n + len(piece) > len(self%data)) then
         allocate (character(len=max(2*len(self%data), self%n + len(piece))) :: grown)
         grown(1:self%n) = self%data(1:self%n)
         call move_alloc(grown, self%data)
      end if
      self%data(self%n + 1:self%n + len(piece)) = piece
      self%n = self%n + len(piece)
   end subroutine buffer_add

   !> The text so far.
   pure function buffer_text(self) result(text)
      !> The buffer.
      class(text_buffer_type), intent(in) :: self
      character(len=:), allocatable :: text
      if (allocated(self%data)) then
         text = self%data(1:self%n)
      else
         text = ''
      end if
   end function buffer_text

   !> Empty the buffer.
   pure subroutine buffer_clear(self)
      !> The buffer.
      class(text_buffer_type), intent(inout) :: self
      self%n = 0
   end subroutine buffer_clear

end module shcontact_core_buffer
