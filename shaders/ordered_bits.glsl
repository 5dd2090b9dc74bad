// Float bits that compare as unsigned integers in the floats' order.
uint ordered(float f) {
  uint bits = floatBitsToUint(f);
  return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}
