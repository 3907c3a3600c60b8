// Loads a template's image (image_format.h): one reader per node kind, the fields in the order
// image_writer.cpp writes them. Every read is bounded by the image, every kind, index and text
// checked; a failure is an ImageFault, which refuses the image.
#include "backends/tmpl/image/image_reader.h"

#include <bit>
#include <cstring>

#include "backends/tmpl/error.h"
#include "backends/tmpl/image/image_bytes.h"
#include "backends/tmpl/image/image_format.h"

namespace smachac::tmpl {

namespace {

[[noreturn]] void fail() { failImage(); }

}  // namespace

/// Reads nodes into an arena (ImageBytes reads the numbers they are made of).
class ImageCursor : public ImageBytes {
 public:
  ImageCursor(ImageReader& reader, Arena& arena, size_t offset)
      : ImageBytes(reader.image_, offset), reader_(reader), arena_(arena) {}

  std::string_view text() {
    uint64_t index = num();
    if (index >= reader_.strings_.size()) fail();
    return reader_.strings_[index];
  }
  const std::string* name() { return internAt(num()); }
  const std::string* optionalName() {
    uint64_t index = num();
    return index ? internAt(index - 1) : nullptr;
  }
  const std::string* internAt(uint64_t index) {
    if (index >= reader_.names_.size()) fail();
    const std::string*& interned = reader_.names_[index];
    if (!interned) interned = intern(reader_.strings_[index]);
    return interned;
  }

  void templateFields(ImageTemplate& out) {
    uint8_t flags = byte();
    out.has_extends = flags & image::kHasExtends;
    out.names_templates = flags & image::kNamesTemplates;
    out.references.resize(count());
    for (auto& [name, pos] : out.references) {
      name = text();
      pos = u32();
    }
    out.blocks.assign(count(), nullptr);
    blocks_ = &out.blocks;
    deferred_ = &out.deferred;
    frame(out.root_frame);
    out.body = body();
    for (const BlockStmt* b : out.blocks) {
      if (!b) fail();
    }
  }

  void macroRecord(MacroStmt* m) {
    m->params.resize(count());
    for (NameExpr*& p : m->params) p = nameExpr();
    m->defaults = exprs();
    m->body = body();
    frame(m->frame);
    m->caller_slot = slot();
    m->kwargs_slot = slot();
    m->varargs_slot = slot();
  }

 private:
  SlotRef ref() {
    SlotRef r;
    r.valid = flag();
    r.up = u16();
    r.slot = u16();
    return r;
  }

  void frame(FrameLayout& layout) {
    layout.num_slots = u16();
    layout.capturable = flag();
    layout.inits.resize(count());
    for (SlotInit& init : layout.inits) {
      uint8_t kind = byte();
      if (kind > static_cast<uint8_t>(SlotInitKind::Undefined)) fail();
      init.kind = static_cast<SlotInitKind>(kind);
      init.slot = u16();
      init.name = name();
      init.hash = hashString(*init.name);
      init.alias = ref();
    }
  }

  std::vector<LocalRef> locals() {
    std::vector<LocalRef> refs(count());
    for (LocalRef& local : refs) {
      local.name = name();
      local.ref = ref();
    }
    return refs;
  }

  std::vector<Expr*> exprs() {
    std::vector<Expr*> items(count());
    for (Expr*& e : items) e = required();
    return items;
  }

  ArgList args() {
    ArgList list;
    list.args = exprs();
    list.kwargs.resize(count());
    for (auto& [name, value] : list.kwargs) {
      name = this->name();
      value = required();
    }
    list.dyn_args = expr();
    list.dyn_kwargs = expr();
    return list;
  }

  Value constant() {
    switch (static_cast<image::ConstKind>(byte())) {
      case image::ConstKind::None:
        return Value::none();
      case image::ConstKind::False:
        return Value::boolean(false);
      case image::ConstKind::True:
        return Value::boolean(true);
      case image::ConstKind::Int:
        return Value::integer(static_cast<int64_t>(num()));
      case image::ConstKind::Float: {
        uint64_t bits = 0;
        for (int i = 0; i < 8; ++i) bits |= uint64_t(byte()) << (8 * i);
        return Value::real(std::bit_cast<double>(bits));
      }
      case image::ConstKind::String:
        return Value::string(std::string(text()));
    }
    fail();
  }

  Expr* required() {
    Expr* e = expr();
    if (!e) fail();
    return e;
  }
  template <class T>
  T* requiredOf(ExprKind kind) {
    Expr* e = required();
    if (e->kind != kind) fail();
    return static_cast<T*>(e);
  }
  NameExpr* nameExpr() { return requiredOf<NameExpr>(ExprKind::Name); }
  template <class T>
  T* optionalOf(ExprKind kind) {
    Expr* e = expr();
    if (e && e->kind != kind) fail();
    return static_cast<T*>(e);
  }

  Expr* expr() {
    uint8_t kind = byte();
    if (kind == image::kNullNode) return nullptr;
    if (kind > static_cast<uint8_t>(ExprKind::NamespaceRef)) fail();
    return exprOf(static_cast<ExprKind>(kind), u32());
  }

  Expr* exprOf(ExprKind kind, uint32_t pos) {
    switch (kind) {
      case ExprKind::Const:
        return arena_.make<ConstExpr>(pos, constant());
      case ExprKind::Name: {
        const std::string* n = name();
        uint8_t ctx = byte();
        if (ctx > static_cast<uint8_t>(NameCtx::Param)) fail();
        auto* e = arena_.make<NameExpr>(pos, n, static_cast<NameCtx>(ctx));
        e->ref = ref();
        return e;
      }
      case ExprKind::List:
      case ExprKind::Tuple: {
        auto* e = arena_.make<SeqExpr>(kind, pos);
        e->items = exprs();
        return e;
      }
      case ExprKind::Dict: {
        auto* e = arena_.make<DictExpr>(pos);
        e->items.resize(count());
        for (auto& [key, value] : e->items) {
          key = required();
          value = required();
        }
        return e;
      }
      case ExprKind::Neg:
      case ExprKind::Pos:
      case ExprKind::Not:
        return arena_.make<UnaryExpr>(kind, pos, required());
      case ExprKind::Binary:
      case ExprKind::And:
      case ExprKind::Or: {
        uint8_t op = byte();
        if (op > static_cast<uint8_t>(BinOp::Pow)) fail();
        Expr* left = required();
        return arena_.make<BinaryExpr>(kind, pos, static_cast<BinOp>(op), left, required());
      }
      default:
        return compound(kind, pos);
    }
  }

  Expr* compound(ExprKind kind, uint32_t pos) {
    switch (kind) {
      case ExprKind::Concat: {
        auto* e = arena_.make<ConcatExpr>(pos);
        e->items = exprs();
        return e;
      }
      case ExprKind::Compare: {
        auto* e = arena_.make<CompareExpr>(pos, required());
        e->ops.resize(count());
        for (auto& [op, operand] : e->ops) {
          uint8_t code = byte();
          if (code > static_cast<uint8_t>(CmpOp::NotIn)) fail();
          op = static_cast<CmpOp>(code);
          operand = required();
        }
        return e;
      }
      case ExprKind::CondExpr: {
        Expr* test = required();
        Expr* then = required();
        return arena_.make<CondExpr>(pos, test, then, expr());
      }
      case ExprKind::Getattr: {
        Expr* object = required();
        return arena_.make<GetattrExpr>(pos, object, name());
      }
      case ExprKind::Getitem: {
        Expr* object = required();
        return arena_.make<GetitemExpr>(pos, object, required());
      }
      case ExprKind::Slice: {
        Expr* start = expr();
        Expr* stop = expr();
        return arena_.make<SliceExpr>(pos, start, stop, expr());
      }
      default:
        return call(kind, pos);
    }
  }

  template <class Def>
  const std::pair<const std::string*, const Def*>& entry(
      const std::vector<std::pair<const std::string*, const Def*>>& table) {
    uint64_t index = num();
    if (index >= table.size()) fail();
    return table[index];
  }

  Expr* call(ExprKind kind, uint32_t pos) {
    switch (kind) {
      case ExprKind::Call: {
        auto* e = arena_.make<CallExpr>(pos, required());
        e->args = args();
        return e;
      }
      case ExprKind::Filter: {
        Expr* input = expr();
        const auto& [name, def] = entry(reader_.filters_);
        auto* e = arena_.make<FilterExpr>(pos, input, name);
        e->def = def;
        e->args = args();
        return e;
      }
      case ExprKind::Test: {
        Expr* input = required();
        const auto& [name, def] = entry(reader_.tests_);
        auto* e = arena_.make<TestExpr>(pos, input, name);
        e->def = def;
        e->args = args();
        return e;
      }
      default: {  // NamespaceRef
        NameExpr* ns = nameExpr();
        return arena_.make<NamespaceRefExpr>(pos, ns, name());
      }
    }
  }

  Body body() {
    Body stmts(count());
    for (Stmt*& s : stmts) s = stmt();
    return stmts;
  }

  Stmt* stmt() {
    uint8_t kind = byte();
    if (kind > static_cast<uint8_t>(StmtKind::Do)) fail();
    uint32_t pos = u32();
    switch (static_cast<StmtKind>(kind)) {
      case StmtKind::Text: {
        uint64_t offset = num();
        uint64_t size = num();
        if (offset > reader_.source_.size() || size > reader_.source_.size() - offset) {
          fail();
        }
        return arena_.make<TextStmt>(pos, reader_.source_.substr(offset, size));
      }
      case StmtKind::Print:
        return arena_.make<PrintStmt>(pos, required());
      case StmtKind::Do:
        return arena_.make<DoStmt>(pos, required());
      case StmtKind::Extends:
        return arena_.make<ExtendsStmt>(pos, required());
      case StmtKind::If:
        return ifStmt(pos);
      case StmtKind::For:
        return forStmt(pos);
      case StmtKind::Block:
        return blockStmt(pos);
      default:
        return importStmt(static_cast<StmtKind>(kind), pos);
    }
  }

  Stmt* ifStmt(uint32_t pos) {
    auto* s = arena_.make<IfStmt>(pos);
    s->branches.resize(count());
    for (auto& [test, branch] : s->branches) {
      test = required();
      branch = body();
    }
    s->orelse = body();
    return s;
  }

  Stmt* forStmt(uint32_t pos) {
    auto* s = arena_.make<ForStmt>(pos);
    s->target = required();
    s->iter = required();
    s->filter = expr();
    s->recursive = flag();
    s->body = body();
    s->orelse = body();
    frame(s->loop_frame);
    frame(s->test_frame);
    frame(s->else_frame);
    s->loop_slot = slot();
    s->test_target_slots.resize(count());
    for (uint16_t& target : s->test_target_slots) target = u16();
    return s;
  }

  Stmt* blockStmt(uint32_t pos) {
    auto* s = arena_.make<BlockStmt>(pos);
    s->name = name();
    s->scoped = flag();
    s->required = flag();
    s->toplevel = flag();
    s->body = body();
    frame(s->frame);
    s->super_slot = slot();
    s->index = u16();
    if (!blocks_ || s->index >= blocks_->size() || (*blocks_)[s->index]) fail();
    (*blocks_)[s->index] = s;
    s->enclosing.resize(count());
    for (const std::string*& enclosing : s->enclosing) enclosing = name();
    s->locals = locals();
    return s;
  }

  Stmt* importStmt(StmtKind kind, uint32_t pos) {
    switch (kind) {
      case StmtKind::Include: {
        auto* s = arena_.make<IncludeStmt>(pos);
        s->template_name = required();
        s->ignore_missing = flag();
        s->with_context = flag();
        s->locals = locals();
        return s;
      }
      case StmtKind::Import: {
        auto* s = arena_.make<ImportStmt>(pos);
        s->template_name = required();
        s->target = nameExpr();
        s->with_context = flag();
        s->toplevel = flag();
        s->locals = locals();
        return s;
      }
      case StmtKind::FromImport: {
        auto* s = arena_.make<FromImportStmt>(pos);
        s->template_name = required();
        s->names.resize(count());
        for (ImportedName& n : s->names) {
          n.name = name();
          n.alias = nameExpr();
        }
        s->with_context = flag();
        s->toplevel = flag();
        s->locals = locals();
        return s;
      }
      default:
        return assignStmt(kind, pos);
    }
  }

  Stmt* assignStmt(StmtKind kind, uint32_t pos) {
    switch (kind) {
      case StmtKind::Set: {
        auto* s = arena_.make<SetStmt>(pos);
        s->target = required();
        s->value = required();
        s->toplevel = flag();
        return s;
      }
      case StmtKind::SetBlock: {
        auto* s = arena_.make<SetBlockStmt>(pos);
        s->target = required();
        s->filter = optionalOf<FilterExpr>(ExprKind::Filter);
        s->body = body();
        frame(s->frame);
        s->toplevel = flag();
        return s;
      }
      case StmtKind::FilterBlock: {
        auto* s = arena_.make<FilterBlockStmt>(pos);
        s->filter = requiredOf<FilterExpr>(ExprKind::Filter);
        s->body = body();
        frame(s->frame);
        return s;
      }
      case StmtKind::With: {
        auto* s = arena_.make<WithStmt>(pos);
        s->targets = exprs();
        s->values = exprs();
        s->body = body();
        frame(s->frame);
        return s;
      }
      case StmtKind::Macro:
        return macroStmt(arena_.make<MacroStmt>(StmtKind::Macro, pos));
      default:  // CallBlock
        return macroStmt(arena_.make<CallBlockStmt>(pos));
    }
  }

  // The header, then the rest inline or (a deferred top-level macro) skipped for later.
  Stmt* macroStmt(MacroStmt* m) {
    m->name = optionalName();
    m->target = optionalOf<NameExpr>(ExprKind::Name);
    m->toplevel = flag();
    m->deferred = flag();
    if (!m->deferred) {
      macroRecord(m);
    } else {
      if (!deferred_ || m->kind != StmtKind::Macro) fail();
      size_t size = count();
      deferred_->push_back({m, offset()});
      skip(size);
    }
    if (m->kind == StmtKind::CallBlock) {
      static_cast<CallBlockStmt*>(m)->call = requiredOf<CallExpr>(ExprKind::Call);
    }
    return m;
  }

  ImageReader& reader_;
  Arena& arena_;
  std::vector<BlockStmt*>* blocks_ = nullptr;
  std::vector<ImageMacro>* deferred_ = nullptr;
};

ImageReader::ImageReader(std::span<const uint8_t> image, std::string_view source)
    : image_(image), source_(source) {}

namespace {

uint64_t fixedAt(const uint8_t* at, int bytes) {
  uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value |= uint64_t(at[i]) << (8 * i);
  return value;
}

std::string_view bytesOf(std::span<const uint8_t> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

// The header: magic, version, and the source and content it was written for.
bool headerFits(std::span<const uint8_t> image, std::string_view source) {
  if (image.size() < image::kHeaderSize) return false;
  if (std::memcmp(image.data(), image::kMagic, 4) != 0 || image[4] != image::kVersion) return false;
  if (fixedAt(&image[5], 4) != source.size()) return false;
  if (fixedAt(&image[9], 8) != image::imageHash(source)) return false;
  return fixedAt(&image[17], 8) == image::imageHash(bytesOf(image.subspan(image::kHeaderSize)));
}

}  // namespace

std::unique_ptr<ImageReader> ImageReader::open(std::span<const uint8_t> image,
                                               std::string_view source, const Registry& registry) {
  if (!headerFits(image, source)) return nullptr;
  auto reader = std::make_unique<ImageReader>(image, source);
  try {
    if (!reader->readTables(registry)) return nullptr;
  } catch (const ImageFault&) {
    return nullptr;
  }
  return reader;
}

// The string table, then the filters and tests, each found in the registry by name.
bool ImageReader::readTables(const Registry& registry) {
  Arena unused;
  ImageCursor cursor(*this, unused, image::kHeaderSize);
  strings_.resize(cursor.count());
  std::vector<size_t> sizes(strings_.size());
  size_t total = 0;
  for (size_t& size : sizes) total += size = cursor.count();
  size_t at = cursor.offset();
  cursor.skip(total);
  for (size_t i = 0; i < strings_.size(); at += sizes[i++])
    strings_[i] = bytesOf(image_.subspan(at, sizes[i]));
  names_.assign(strings_.size(), nullptr);
  filters_.resize(cursor.count());
  for (auto& [name, def] : filters_) {
    name = cursor.name();
    def = registry.filter(*name);
    if (!def) return false;
  }
  tests_.resize(cursor.count());
  for (auto& [name, def] : tests_) {
    name = cursor.name();
    def = registry.test(*name);
    if (!def) return false;
  }
  content_ = cursor.offset();
  return true;
}

bool ImageReader::readTemplate(Arena& arena, ImageTemplate& out) {
  try {
    ImageCursor cursor(*this, arena, content_);
    cursor.templateFields(out);
    return cursor.offset() == image_.size();
  } catch (const ImageFault&) {
    return false;
  }
}

void ImageReader::readMacro(const ImageMacro& deferred, Arena& arena) {
  try {
    ImageCursor cursor(*this, arena, deferred.offset);
    cursor.macroRecord(deferred.macro);
  } catch (const ImageFault&) {
    throw Fault("the precompiled image of a macro does not read");
  }
}

}  // namespace smachac::tmpl
