!> Reads lines "tag hex" (scripts/fuzz_primitives.py) and writes the argument, the
!! result of the library's primitive and of the intrinsic, in hex: tags hw, dr (binary128
!! in: hardware_real, double_real), qr (x87 in: quad_real), sq, is, ex, em (fast_sqrt,
!! inverse_sqrt, fast_exp, fast_expm1; the intrinsic 1/sqrt, exp, libquadmath expm1).
program harness
    use brachistochrone_kinds, only: qp, xp
    use brachistochrone_fast_math, only: fast_sqrt, inverse_sqrt, quad_real, hardware_real, &
                                         double_real
    use brachistochrone_fast_exp, only: fast_exp, fast_expm1
    use brachistochrone_quad_math, only: expm1
    use, intrinsic :: iso_fortran_env, only: int64, int16, real64
    implicit none
    integer, parameter :: i128 = selected_int_kind(38)
    character(len=80) :: line
    character(len=2) :: tag
    integer(int64) :: w(2), v(2)
    integer(i128) :: b
    real(qp) :: x, y, z
    real(xp) :: a, c, d
    real(real64) :: r1, r2
    integer :: ios
    do
        read(*, '(a)', iostat=ios) line
        if (ios /= 0) exit
        tag = line(1:2)
        select case (tag)
        case ('qr')  ! x87 bits: sign/exponent 4 hex, significand 16 hex
            read(line(4:7), '(z4)') w(2)
            read(line(8:23), '(z16)') w(1)
            a = transfer(w, a)
            x = quad_real(a)
            y = real(a, qp)
            write(*, '(a,1x,a,1x,z32.32,1x,z32.32)') tag, trim(line(4:23)), &
                transfer(x, b), transfer(y, b)
        case default
            read(line(4:35), '(z32)') b
            x = transfer(b, x)
            select case (tag)
            case ('hw')
                a = hardware_real(x)
                c = real(x, xp)
                w = transfer(a, w)
                v = transfer(c, v)
                write(*, '(a,1x,z32.32,1x,z4.4,z16.16,1x,z4.4,z16.16)') tag, b, &
                    iand(w(2), 65535_int64), w(1), iand(v(2), 65535_int64), v(1)
            case ('dr')
                r1 = double_real(x)
                r2 = real(x, real64)
                write(*, '(a,1x,z32.32,1x,z16.16,1x,z16.16)') tag, b, &
                    transfer(r1, 0_int64), transfer(r2, 0_int64)
            case ('sq')
                y = fast_sqrt(x)
                z = sqrt(x)
                write(*, '(a,1x,z32.32,1x,z32.32,1x,z32.32)') tag, b, transfer(y, b), &
                    transfer(z, b)
            case ('is')
                y = inverse_sqrt(x)
                z = 1.0_qp/sqrt(x)
                write(*, '(a,1x,z32.32,1x,z32.32,1x,z32.32)') tag, b, transfer(y, b), &
                    transfer(z, b)
            case ('ex')
                y = fast_exp(x)
                z = exp(x)
                write(*, '(a,1x,z32.32,1x,z32.32,1x,z32.32)') tag, b, transfer(y, b), &
                    transfer(z, b)
            case ('em')
                y = fast_expm1(x)
                z = expm1(x)
                write(*, '(a,1x,z32.32,1x,z32.32,1x,z32.32)') tag, b, transfer(y, b), &
                    transfer(z, b)
            end select
        end select
    end do
end program harness
