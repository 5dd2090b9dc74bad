// For translucent scene items drawn after SceneBackground: the ground it drew
// by compute is not in the depth buffer, so a fragment behind the scene's
// depth (texture unit 8, window depth) is discarded by hand.
layout(binding = 8) uniform sampler2D uSceneDepthOcclusion;

bool behindScene() { return gl_FragCoord.z > texelFetch(uSceneDepthOcclusion, ivec2(gl_FragCoord.xy), 0).r; }
