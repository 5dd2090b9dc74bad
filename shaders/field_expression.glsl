// A field written at run time (field.mode = expression): the twin of
// FieldExpression::evaluate (core/expr/field_expression.h). FIELD_EXPRESSION
// programs are compiled with EXPRESSION_X, _Y and _Z defined as GLSL made by
// expressionToGlsl (core/expr/expression_glsl.h), whose variables are the
// e_ names below.

#ifdef FIELD_EXPRESSION
// muParser's a^b (C's pow): a negative base with a whole exponent is defined.
float e_pow(float a, float b) {
  if (b == 0.0) return 1.0;
  if (a == 0.0) return b > 0.0 ? 0.0 : 1.0 / a;
  if (a > 0.0) return pow(a, b);
  if (b != floor(b)) return sqrt(a);  // NaN, as C gives
  float r = pow(-a, b);
  return mod(b, 2.0) == 0.0 ? r : -r;
}

vec3 expressionAt(vec3 p, float t, vec3 v, float age) {
  float e_x = p.x, e_y = p.y, e_z = p.z, e_t = t;
  float e_vx = v.x, e_vy = v.y, e_vz = v.z, e_age = age;
  return vec3(EXPRESSION_X, EXPRESSION_Y, EXPRESSION_Z);
}
#endif
