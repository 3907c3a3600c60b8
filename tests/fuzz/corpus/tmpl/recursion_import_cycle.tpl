{% import 'importer.tpl' as i %}{{ i }}
