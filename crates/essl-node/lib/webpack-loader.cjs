// The webpack loader (`essl/webpack`): checks a shader file or a script that holds shaders;
// an error fails the build with essl's message at the author's file, line and column, a
// warning is a webpack warning. A shader file's output is the text WebGL is given (its
// `#include`s in place), minified under `minify: true`: use it with `type: 'asset/source'`. A
// script passes through as it is, with the source map and metadata the loaders before it made.
module.exports = function esslLoader(source, map, meta) {
  const callback = this.async();
  const options = this.getOptions ? this.getOptions() : {};
  const id = this.resourcePath + (this.resourceQuery || '');
  import('./core.js')
    .then(async ({checkModule, buildError, SHADER, optionsError, wanted}) => {
      const bad = optionsError('essl/webpack', options);
      if (bad) return callback(bad);
      if (!wanted(id, options)) return callback(null, source, map, meta);
      // `source` is the module's text as the loaders before this one left it.
      const checked = await checkModule(id, source, options, true);
      if (!checked) return callback(null, source, map, meta);
      for (const f of checked.files) this.addDependency(f);
      for (const w of checked.warnings) this.emitWarning(new Error(w.rendered));
      if (checked.errors.length) return callback(buildError(checked.errors));
      const shader = SHADER.test(this.resourcePath) && checked.text !== null;
      // A text other than the source (includes in place, minified) has no map from it.
      if (shader && checked.text !== source) return callback(null, checked.text);
      return callback(null, source, map, meta);
    })
    .catch(callback);
};
