// Put before the module's glue (emcc --extern-pre-js). The glue, made as an ES module, still
// reads __dirname when it runs in Node, where an ES module has none; the module is inside the
// JavaScript (SINGLE_FILE) and reads no file, so an empty folder is all it needs.
var __dirname = '';
