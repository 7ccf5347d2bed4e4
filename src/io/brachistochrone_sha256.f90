!> SHA-256 (FIPS 180-4) of a byte string, for the provenance of result files: the input's
!! checksum identifies it without echoing it, and lets a merge of job-array slices check
!! that they came from the same input.
module brachistochrone_sha256
    use, intrinsic :: iso_fortran_env, only: int32, int64, int8
    implicit none
    private

    public :: sha256_hex

    !> Round constants: the first 32 bits of the fractional parts of the cube roots of
    !! the first 64 primes (FIPS 180-4, sec. 4.2.2).
    integer(int64), parameter :: k_round(0:63) = [ &
        int(z'428a2f98', int64), int(z'71374491', int64), int(z'b5c0fbcf', int64), &
        int(z'e9b5dba5', int64), int(z'3956c25b', int64), int(z'59f111f1', int64), &
        int(z'923f82a4', int64), int(z'ab1c5ed5', int64), int(z'd807aa98', int64), &
        int(z'12835b01', int64), int(z'243185be', int64), int(z'550c7dc3', int64), &
        int(z'72be5d74', int64), int(z'80deb1fe', int64), int(z'9bdc06a7', int64), &
        int(z'c19bf174', int64), int(z'e49b69c1', int64), int(z'efbe4786', int64), &
        int(z'0fc19dc6', int64), int(z'240ca1cc', int64), int(z'2de92c6f', int64), &
        int(z'4a7484aa', int64), int(z'5cb0a9dc', int64), int(z'76f988da', int64), &
        int(z'983e5152', int64), int(z'a831c66d', int64), int(z'b00327c8', int64), &
        int(z'bf597fc7', int64), int(z'c6e00bf3', int64), int(z'd5a79147', int64), &
        int(z'06ca6351', int64), int(z'14292967', int64), int(z'27b70a85', int64), &
        int(z'2e1b2138', int64), int(z'4d2c6dfc', int64), int(z'53380d13', int64), &
        int(z'650a7354', int64), int(z'766a0abb', int64), int(z'81c2c92e', int64), &
        int(z'92722c85', int64), int(z'a2bfe8a1', int64), int(z'a81a664b', int64), &
        int(z'c24b8b70', int64), int(z'c76c51a3', int64), int(z'd192e819', int64), &
        int(z'd6990624', int64), int(z'f40e3585', int64), int(z'106aa070', int64), &
        int(z'19a4c116', int64), int(z'1e376c08', int64), int(z'2748774c', int64), &
        int(z'34b0bcb5', int64), int(z'391c0cb3', int64), int(z'4ed8aa4a', int64), &
        int(z'5b9cca4f', int64), int(z'682e6ff3', int64), int(z'748f82ee', int64), &
        int(z'78a5636f', int64), int(z'84c87814', int64), int(z'8cc70208', int64), &
        int(z'90befffa', int64), int(z'a4506ceb', int64), int(z'bef9a3f7', int64), &
        int(z'c67178f2', int64)]
    !> Initial hash value (FIPS 180-4, sec. 5.3.3).
    integer(int64), parameter :: h_initial(0:7) = [ &
        int(z'6a09e667', int64), int(z'bb67ae85', int64), int(z'3c6ef372', int64), &
        int(z'a54ff53a', int64), int(z'510e527f', int64), int(z'9b05688c', int64), &
        int(z'1f83d9ab', int64), int(z'5be0cd19', int64)]
    !> 2^32 - 1: words are kept in the low 32 bits of 64-bit integers.
    integer(int64), parameter :: mask32 = int(z'ffffffff', int64)

contains

    !> The SHA-256 digest of `text` (its bytes), as 64 lowercase hexadecimal digits.
    pure function sha256_hex(text) result(hex)
        character(len=*), intent(in) :: text !! the bytes
        character(len=64) :: hex
        character(len=*), parameter :: digits = '0123456789abcdef'
        integer(int64) :: state(0:7)
        character(len=64) :: last(2)
        integer(int64) :: bits
        integer :: n, full, tail, k, j, blocks
        n = len(text)
        state = h_initial
        full = n/64
        do k = 0, full - 1
            call compress(state, text(64*k + 1:64*k + 64))
        end do
        ! padding: 0x80, zeros, the length in bits as a 64-bit big-endian number
        tail = n - 64*full
        last = repeat(achar(0), 64)
        last(1)(1:tail) = text(64*full + 1:n)
        last(1)(tail + 1:tail + 1) = achar(128)
        blocks = merge(1, 2, tail <= 55)
        bits = 8_int64*int(n, int64)
        do j = 0, 7
            last(blocks)(64 - j:64 - j) = achar(int(iand(shiftr(bits, 8*j), 255_int64)))
        end do
        do k = 1, blocks
            call compress(state, last(k))
        end do
        do k = 0, 7
            do j = 0, 7
                hex(8*k + j + 1:8*k + j + 1) = digits(int(iand(shiftr(state(k), &
                    4*(7 - j)), 15_int64)) + 1:int(iand(shiftr(state(k), 4*(7 - j)), &
                    15_int64)) + 1)
            end do
        end do
    end function sha256_hex

    !> One 64-byte block into the state (FIPS 180-4, sec. 6.2.2).
    pure subroutine compress(state, block)
        integer(int64), intent(inout) :: state(0:7)
        character(len=64), intent(in) :: block
        integer(int64) :: w(0:63), v(0:7), t1, t2, s0, s1
        integer :: j
        do j = 0, 15
            w(j) = ior(ior(shiftl(byte(4*j + 1), 24), shiftl(byte(4*j + 2), 16)), &
                       ior(shiftl(byte(4*j + 3), 8), byte(4*j + 4)))
        end do
        do j = 16, 63
            s0 = ieor(ieor(rotr(w(j - 15), 7), rotr(w(j - 15), 18)), shiftr(w(j - 15), 3))
            s1 = ieor(ieor(rotr(w(j - 2), 17), rotr(w(j - 2), 19)), shiftr(w(j - 2), 10))
            w(j) = iand(w(j - 16) + s0 + w(j - 7) + s1, mask32)
        end do
        v = state
        do j = 0, 63
            s1 = ieor(ieor(rotr(v(4), 6), rotr(v(4), 11)), rotr(v(4), 25))
            t1 = v(7) + s1 + ieor(iand(v(4), v(5)), iand(ieor(v(4), mask32), v(6))) &
                 + k_round(j) + w(j)
            s0 = ieor(ieor(rotr(v(0), 2), rotr(v(0), 13)), rotr(v(0), 22))
            t2 = s0 + ieor(ieor(iand(v(0), v(1)), iand(v(0), v(2))), iand(v(1), v(2)))
            v(7) = v(6)
            v(6) = v(5)
            v(5) = v(4)
            v(4) = iand(v(3) + t1, mask32)
            v(3) = v(2)
            v(2) = v(1)
            v(1) = v(0)
            v(0) = iand(t1 + t2, mask32)
        end do
        state = iand(state + v, mask32)
    contains
        pure integer(int64) function byte(position)
            integer, intent(in) :: position
            byte = int(iachar(block(position:position)), int64)
        end function byte
    end subroutine compress

    !> Rotate the low 32 bits of x right by n.
    elemental integer(int64) function rotr(x, n)
        integer(int64), intent(in) :: x
        integer, intent(in) :: n
        rotr = iand(ior(shiftr(x, n), shiftl(x, 32 - n)), mask32)
    end function rotr

end module brachistochrone_sha256
