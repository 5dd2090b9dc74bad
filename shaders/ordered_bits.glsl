// Float bits that compare as unsigned integers in the floats' order.
uint ordered(float f) {
  uint bits = floatBitsToUint(f);
  return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}
// The float whose ordered() bits these are.
float fromOrdered(uint o) {
  return uintBitsToFloat((o & 0x80000000u) != 0u ? o & 0x7fffffffu : ~o);
}
