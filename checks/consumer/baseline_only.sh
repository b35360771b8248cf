#!/usr/bin/env bash
# Fails when a library uses an x86-64 instruction beyond the baseline (SSE2) that every amd64 CPU runs:
# what -march=native would add on a newer machine. Usage: baseline_only.sh ARCHIVE...
# It disassembles every member (objdump -d) and looks each instruction's mnemonic up among the later
# extensions' own: every VEX/EVEX-encoded one (AVX, AVX2, FMA, F16C, AVX-512: the mnemonics that begin
# with v, and AVX-512's mask-register k-instructions), SSE3, SSSE3, SSE4.1/4.2, POPCNT, LZCNT, BMI1/2,
# ADX and MOVBE. Limits: the list is the check (an extension it leaves out, such as AES-NI or SHA, is
# not seen); TZCNT is left out because baseline compilers emit `rep bsf`, which objdump prints as tzcnt
# and which older CPUs run as bsf; it proves nothing on a building CPU that has none of these extensions
# (there -march=native adds nothing to find); and it only knows x86-64 (elsewhere it says so and passes).
set -euo pipefail
if [[ $(uname -m) != x86_64 ]]; then
  echo "baseline_only: x86-64 only, not checked on $(uname -m)"
  exit 0
fi
later='v[a-z0-9]+|k(add|and|andn|mov|not|or|ortest|shiftl|shiftr|test|unpck|xnor|xor)[bwdq]?'
later+='|addsubp[sd]|h(add|sub)p[sd]|lddqu|movddup|movs[hl]dup|fisttp[sl]?l?'
later+='|pabs[bwd]|palignr|ph(add|sub)(w|d|sw)|pmaddubsw|pmulhrsw|pshufb|psign[bwd]'
later+='|blendv?p[sd]|dpp[sd]|extractps|insertps|movntdqa|mpsadbw|packusdw|pblendvb|pblendw|pcmpeqq'
later+='|pextr[bdq]|phminposuw|pinsr[bdq]|pmaxs[bd]|pmaxu[wd]|pmins[bd]|pminu[wd]|pmov[sz]x[bwd][wdq]'
later+='|pmuldq|pmulld|ptest|round[ps][sd]'
later+='|pcmp[ei]stri|pcmp[ei]strm|pcmpgtq|crc32[bwlq]?'
later+='|popcnt[wlq]?|lzcnt[wlq]?|andn[lq]?|bextr[lq]?|blsi[lq]?|blsmsk[lq]?|blsr[lq]?|bzhi[lq]?'
later+='|mulx[lq]?|pdep[lq]?|pext[lq]?|rorx[lq]?|sarx[lq]?|shlx[lq]?|shrx[lq]?|adcx[lq]?|adox[lq]?|movbe[wlq]?'
status=0
for archive in "$@"; do
  # The mnemonic is the first word after the address's tab, past any prefix (lock, rep, segment, ...).
  found=$(objdump -d --no-show-raw-insn "$archive" | awk -F'\t' -v later="^($later)\$" '
    NF >= 2 && $1 ~ /^ *[0-9a-f]+:$/ {
      n = split($2, word, " ")
      for (i = 1; i < n && word[i] ~ /^(lock|rep|repz|repnz|repe|repne|notrack|bnd|data16|addr32|[c-gs]s|rex[.a-z0-9]*)$/; ++i) {}
      if (word[i] ~ later && word[i] !~ /^ver[rw]$/) count[word[i]]++
    }
    END { for (m in count) print count[m], m }' | sort -k1,1nr -k2 | awk '
    { ++kinds; if (kinds <= 8) top = top " " $2 "×" $1 }
    END { if (kinds) printf "%d kinds, most used:%s", kinds, top }')
  if [[ -n $found ]]; then
    echo "baseline_only: $archive uses instructions beyond x86-64: $found" >&2
    status=1
  else
    echo "baseline_only: $archive: x86-64 baseline only"
  fi
done
exit $status
