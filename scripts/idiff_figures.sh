# Sourced by the accuracy scripts. idiff_figures A B prints idiff -a's PSNR,
# mean error and max error of image A against B, space-separated ("-" for a
# figure idiff did not print). idiff exits non-zero when the images differ:
# only its figures matter here.
idiff_figures() {
  local cmp psnr mean max
  cmp=$(idiff -a "$1" "$2" 2>&1 || true)
  psnr=$(sed -n 's/.*Peak SNR = \([0-9.inf]*\).*/\1/p' <<<"$cmp" | head -1)
  mean=$(sed -n 's/.*Mean error = \([0-9.e+-]*\).*/\1/p' <<<"$cmp" | head -1)
  max=$(sed -n 's/.*Max error  = \([0-9.e+-]*\).*/\1/p' <<<"$cmp" | head -1)
  echo "${psnr:--} ${mean:--} ${max:--}"
}
